"""HDF5 pieces shared by the readers: text decoding, lazy datasets, dimension scales, records."""
import h5py
import numpy as np
import xarray as xr
from xarray.backends import BackendArray
from xarray.core import indexing

# HDF5 bookkeeping that says nothing to a reader of the Dataset.
_HIDDEN_ATTRS = {"CLASS", "NAME", "DIMENSION_LIST", "REFERENCE_LIST", "_Netcdf4Dimid", "_Netcdf4Coordinates"}
# Datasets up to this many values are read at once; larger ones stay on disk until used.
_EAGER_VALUES = 1 << 16


def text(value):
    """str of an HDF5 string (bytes, numpy bytes, 0-d array); other values unchanged."""
    if isinstance(value, np.ndarray) and value.shape == ():
        value = value[()]
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode("utf-8")
    return value


def plain(value):
    """An attribute value fit for xarray and netCDF: str for strings, Python scalars, arrays of str."""
    value = text(value)
    if isinstance(value, np.ndarray) and value.dtype.kind in "SO":
        return np.array([text(v) for v in value.ravel()], dtype=object).reshape(value.shape)
    if isinstance(value, np.generic):
        return value.item()
    return value


def attributes(obj, skip=()):
    return {k: plain(v) for k, v in obj.attrs.items() if k not in _HIDDEN_ATTRS and k not in skip}


class _LazyDataset(BackendArray):
    """An h5py dataset read only where indexed (xarray's documented backend-array protocol)."""

    def __init__(self, dataset):
        self._dataset = dataset
        self.shape = dataset.shape
        self.dtype = dataset.dtype

    def __getitem__(self, key):
        return indexing.explicit_indexing_adapter(key, self.shape, indexing.IndexingSupport.BASIC, self._read)

    def _read(self, key):
        return np.asarray(self._dataset[key])


def values(dataset):
    """Strings decoded to str; small numbers read now, large ones lazily."""
    if dataset.dtype.kind in "SO" or h5py.check_string_dtype(dataset.dtype) is not None:
        raw = dataset[()]
        return np.array([text(v) for v in np.ravel(raw)], dtype=object).reshape(np.shape(raw))
    if dataset.size <= _EAGER_VALUES:
        return dataset[()]
    return indexing.LazilyIndexedArray(_LazyDataset(dataset))


def is_scale(dataset):
    return text(dataset.attrs.get("CLASS", b"")) == "DIMENSION_SCALE"


def basename(path):
    return path.rsplit("/", 1)[-1]


def scale_dims(dataset):
    """Each axis's name from its attached dimension scale (None where none is attached)."""
    if is_scale(dataset):
        return [basename(dataset.name)]
    dims = []
    for axis in dataset.dims:
        dims.append(basename(axis[0].name) if len(axis) else None)
    return dims


def variable(dataset, dims, extra_attrs=None):
    attrs = attributes(dataset)
    attrs["hdf5_path"] = dataset.name
    attrs.update(extra_attrs or {})
    return xr.Variable(dims, values(dataset), attrs)


def option_record(group):
    """The option record (values as attributes, units/ and origin/ subgroups) as
    {name: (value, unit, origin)}."""
    units = attributes(group["units"]) if "units" in group else {}
    origins = attributes(group["origin"]) if "origin" in group else {}
    return {k: (v, units.get(k, ""), origins.get(k, "")) for k, v in attributes(group).items()}


def provenance(group):
    """Where the file came from (io::writeProvenance), as Dataset attributes: the record's
    attributes, and the -options_file paths and texts as two lists of equal length."""
    attrs = attributes(group)
    files = attributes(group["options_files"]) if "options_files" in group else {}
    attrs["options_files"] = list(files)
    attrs["options_files_text"] = [files[k] for k in files]
    return attrs


def collect(root, plain_groups, fallback_dims=None, skip=()):
    """Every dataset under root as (coords, data_vars) of xarray Variables. Dimension scales become
    coordinates named by their dataset; datasets of plain_groups keep their names, the others are
    named by their path with '/' -> '_'. fallback_dims[path] names the axes of a dataset without
    scales; a dataset with an unnamed axis and no fallback is an error (the file is not one we know)."""
    fallback_dims = fallback_dims or {}
    coords, data = {}, {}

    def visit(path, obj):
        if not isinstance(obj, h5py.Dataset) or path in skip or path.split("/")[0] in skip:
            return
        group, name = path.rsplit("/", 1) if "/" in path else ("", path)
        dims = fallback_dims.get(path) or scale_dims(obj)
        if None in dims:
            raise ValueError(f"{root.file.filename}: /{path} has an axis without a name")
        if is_scale(obj):
            target, key = coords, name
        else:
            target, key = data, name if group in plain_groups else path.replace("/", "_")
        if key in coords or key in data:
            raise ValueError(f"{root.file.filename}: two datasets would be named {key}")
        target[key] = variable(obj, dims)

    root.visititems(visit)
    return coords, data


class _MaskedHistory(BackendArray):
    """A [point, realisation, sample] history read only where indexed, NaN at samples at or past
    the task's length (lengths: int array [point, realisation])."""

    def __init__(self, dataset, lengths):
        self._dataset, self._lengths = dataset, lengths
        self.shape, self.dtype = dataset.shape, dataset.dtype

    def __getitem__(self, key):
        return indexing.explicit_indexing_adapter(key, self.shape, indexing.IndexingSupport.BASIC, self._read)

    def _read(self, key):
        key = tuple(key) + (slice(None),) * (len(self.shape) - len(tuple(key)))
        return mask_history(np.array(self._dataset[key]), self._lengths, key, self.shape)


def mask_history(values, lengths, key, shape):
    """values = history[key] with NaN where the sample index >= lengths[point, realisation]."""
    point, realisation, sample = (np.atleast_1d(np.arange(n)[k]) for n, k in zip(shape, key))
    past = sample[None, None, :] >= lengths[np.ix_(point, realisation)][:, :, None]
    if past.any():
        values = np.array(values, dtype=float)
        values[past.reshape(values.shape)] = np.nan
    return values


def masked_history(variable, dataset, lengths):
    """variable (read from dataset, dims [point, realisation, sample]) masked past each task's
    length: the same Variable, its values NaN from sample lengths[point, realisation] on."""
    if dataset.dtype.kind != "f" or lengths.shape != dataset.shape[:2]:
        return variable
    if dataset.size <= _EAGER_VALUES:
        data = mask_history(np.asarray(variable.values), lengths, (slice(None),) * 3, dataset.shape)
    else:
        data = indexing.LazilyIndexedArray(_MaskedHistory(dataset, lengths))
    return xr.Variable(variable.dims, data, variable.attrs)
