"""Read any gradfric results file as one xarray Dataset.

    import gradfric
    ds = gradfric.open("fig4.h5")          # ensemble, FEM run, FEM sweep, study, design, calibration
    ds["mu_s_relative"].swap_dims(point="delta").plot()

What open() returns, by the file's `format` (attribute Dataset.attrs["format"]):
  gradfric-sbm-ensemble (docs/ensemble.md): dims point, realisation, sample, block_row,
      block_column, snapshot; the /sweep columns (delta, theta, sigma, sigma_kinetic, property,
      profile, reference_point, field_value) are coordinates along point, `time` (history sample
      times) along (point, realisation, sample), x and y the block centres [m]. /realisations,
      /statistics, /history and /maps keep their names (mu_s, mu_s_mean, mu, first_slip_time, ...);
      /properties and /run are prefixed (properties_mu_s, run_wall_seconds).
  gradfric-fem-sweep (docs/fem.md): the same, for the FEM: dims point, realisation, sample and
      the bottom cells cell_x (properties_E, ...: the column centres [m] are its coordinate) and,
      with property fields, cell_y (properties_mu_s_map, ...); no sigma, sigma_kinetic,
      redrawn_blocks, /maps, x or y. Files of format version 3 have block_row, block_column, x, y,
      sigma and redrawn_blocks as the spring-block files have them, and read so.
  gradfric-fem-run (docs/fem.md): one gradfric-fem run, read as a FEM sweep (one point, one
      realisation, without reference_point or <name>_relative, <name>_relative_ci95: a single run
      has no reference; files of format version 3 hold them, NaN or 0) plus its /fem extras: dims
      cell_x (fem_properties_E), node_x (fem_properties_mu_s, ...: the values the physics used),
      cell_y (fem_fields_mu_s_map, ...), node_y (pressure_response_g); normal_force along (point,
      realisation, sample); each /fem/results attribute as a 0-d variable (first_slip_time, dt,
      ...); /fem/derived as attributes.
  gradfric-fem-history (a single run before the campaign layout, format versions 1 to 4): dim
      time (mu, force_x, ...), x (properties_E), node_x, y (fields_mu_s_map, ...), node_y
      (pressure_response_g); each /results attribute as a 0-d variable (mu_s, peak_time, ...).
  gradfric-accuracy-study (docs/accuracy.md): dims ladder, rung; setting, mu_s_error, ...
      (NaN past a ladder's last rung); knob, setting_unit, error_meaning per ladder.
  gradfric-design (docs/design.md): dim evaluation (x_<parameter>, value, ci95_low, ...; phase);
      design_<column>, verification_<column>, fem_verification_<column> as 0-d variables;
      with -design_variants, dim variant (variants_<column>; attributes variants_files, variants_options).
  gradfric-calibration-curves / -scene (docs/calibration.md): the CSV of -calibrate_curve along
      time (with the .opts of the same name, its fit), or the .opts alone: lz, sigma, ...

Histories (dim sample) end at the longest /history/length of the file's tasks, and each task's
is NaN past its own length (point, realisation): open() masks them so whatever the file holds
there, `.dropna("sample")` or `[:length]` gives one history. A single FEM run's hold its samples
alone, no NaN (its file stores no padding from format version 4; older files are cut here).
Files before format version 3 (mu_*_relative_error) also get mu_*_relative_ci95.

    ds = gradfric.run("input/sbm_fig4_reduced.opts", ranks=2, sbm_N=16)   # runs a driver, then open()

run() (gradfric._run) runs a driver under mpiexec and returns its results file read by open();
RunError carries a failed run's one-line message and exit code (2: bad input).

Every variable has `units` and `description` attributes and `hdf5_path`, the dataset it came from
(`/results@mu_s`: an attribute); strings are str. Dataset attributes: the file's root attributes, the scene's options (names
without the dash, values as text; scene_options lists them; options() gives units and origins)
and the provenance record (software_version, software_commit, command_line, date, ranks,
options_files with options_files_text). Large datasets are read when used: close the Dataset
(or use it in a `with`) to release the file.
Needs Debian's python3-h5py, python3-numpy, python3-xarray. Install: docs/running.md, "Reading
results in Python" (pip install --no-deps --no-build-isolation ./python), or use python/ in place.
"""
import builtins

import h5py

from . import _calibration, _ensemble, _fem, _tables
from ._run import RunError, driver_folders, find_driver, run

# The project's version (CMakeLists.txt project(gradfric VERSION ...)); pyproject.toml reads it from
# here, test python_package checks that the two agree.
__version__ = "0.1.0"

__all__ = ["open", "options", "run", "RunError", "find_driver", "driver_folders", "__version__"]

_READERS = {}
for _formats, _reader in ((_ensemble.FORMATS, _ensemble.read), (_fem.FORMATS, _fem.read),
                          (_tables.STUDY_FORMATS, _tables.read_study), (_tables.DESIGN_FORMATS, _tables.read_design)):
    _READERS.update(dict.fromkeys(_formats, _reader))


def _read(path):
    """(Dataset, scene record {name: (value, unit, origin)})."""
    if h5py.is_hdf5(path):
        f = h5py.File(path, "r")
        try:
            kind = f.attrs.get("format", b"")
            kind = kind.decode() if isinstance(kind, bytes) else str(kind)
            if kind not in _READERS:
                raise ValueError(f"{path} is not a gradfric results file (format {kind!r})")
            ds, scene = _READERS[kind](f)
        except BaseException:
            f.close()
            raise
        ds.set_close(f.close)
        return ds, scene
    with builtins.open(path, encoding="utf-8", errors="replace") as text:
        first = text.readline()
    if _calibration.is_curves(first):
        return _calibration.read_curves(path)
    if _calibration.is_scene(first):
        return _calibration.read_scene(path)
    raise ValueError(f"{path} is not a gradfric results file (neither HDF5 nor a gradfric-calibrate file)")


def open(path):  # noqa: A001 (gradfric.open, as xarray.open_dataset)
    """The results file at path as an xarray Dataset (see the module's help)."""
    return _read(str(path))[0]


def options(path):
    """The scene's options of a results file: {name: (value, unit, origin)} (the option record
    /scene of the ensemble, FEM sweep and FEM files; {} for the others)."""
    ds, scene = _read(str(path))
    ds.close()
    return scene
