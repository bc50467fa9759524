#!/usr/bin/env bash
# Every refusal of a property field, before any work: exit code 2, one message naming the option
# (and, for values out of range, the value and where on the plate), no results file left; on 2
# ranks as well (every rank refuses, no hang).
# Usage: refusals.sh <gradfric driver> <gradfric-fem driver> <source dir> <scratch folder>
set -u
sbm=$1
fem=$2
source_dir=$3
scratch=$4
mkdir -p "$scratch"
out="$scratch/refused.h5"
failures=0
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

# Bad maps, written here: NaN, rank 3, too small an extent, no extent, not an image, colour PNG.
/usr/bin/python3 - "$scratch" <<'PY'
import struct, sys, zlib
import h5py, numpy as np
d = sys.argv[1]
L = 5e-3
def h5(name, data, extent=(0, L, 0, L)):
    with h5py.File(f"{d}/{name}", "w") as f:
        ds = f.create_dataset("factor", data=data)
        if extent is not None:
            ds.attrs["extent"] = np.array(extent, dtype=float)
nan = np.ones((8, 8)); nan[5, 2] = np.nan
h5("nan.h5", nan)
h5("rank3.h5", np.ones((2, 8, 8)))
h5("small.h5", np.ones((8, 8)), (0, L / 2, 0, L))
h5("noextent.h5", np.ones((8, 8)), None)
h5("negative.h5", np.full((8, 8), -0.5))
open(f"{d}/text.png", "w").write("not an image\n")
def chunk(k, b): return struct.pack(">I", len(b)) + k + b + struct.pack(">I", zlib.crc32(k + b) & 0xFFFFFFFF)
raw = b"".join(b"\x00" + bytes([200, 10, 10] * 4) for _ in range(4))
with open(f"{d}/colour.png", "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 4, 4, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
PY

# expect <ranks> <driver> <output option> <text the message must contain ...> -- <arguments...>
source "$source_dir/tests/common/expect_refusal.sh"
s() { expect 1 "$sbm" -output "$@"; }

# Values out of range somewhere on the plate: the option, its value, the property and where.
s "-field_E_delta = 1.5" "E > 0" "E = -" "x = 6.25e-05 m" -- -sbm_N 40 -field_E_profile linear -field_E_delta 1.5
s "-field_mu_k_delta = 0.8" "mu_k <= mu_s" -- -field_mu_k_profile constant -field_mu_k_delta 0.8
s "-field_p_delta = -1.2" "p > 0" -- -field_p_profile step -field_p_delta -1.2 -field_p_position 1e-3
s "-field_p_normalise = false" "keeps its mean" -- -field_p_profile linear -field_p_delta 0.3 -field_p_normalise false
s "-field_mu_s_values = 1,0,1" "mu_s > 0" "x = " -- -field_mu_s_profile bands -field_mu_s_values 1,0,1
s "-field_mu_map = $scratch/negative.h5" "mu_s > 0" -- -field_mu_profile map -field_mu_map "$scratch/negative.h5"
s "-field_mu_exponent = 0" "> 0 for the power law" -- -field_mu_profile power -field_mu_exponent 0
# Maps: NaN (with the pixel and its place), rank, extent, unreadable, colour, missing, unknown kind.
s "-field_mu_map" "finite values" "pixel 2, 5" -- -field_mu_profile map -field_mu_map "$scratch/nan.h5"
s "-field_E_map" "rank-2" "has rank 3" -- -field_E_profile map -field_E_map "$scratch/rank3.h5" -sbm_N 8
s "-field_mu_map" "covers the plate" -- -field_mu_profile map -field_mu_map "$scratch/small.h5"
s "-field_mu_map" "attribute 'extent'" -- -field_mu_profile map -field_mu_map "$scratch/noextent.h5"
s "-field_mu_map" "dataset 'other'" -- -field_mu_profile map -field_mu_map "$scratch/nan.h5" -field_mu_map_dataset other
s "-field_mu_map" "readable PNG" -- -field_mu_profile map -field_mu_map "$scratch/text.png"
s "-field_mu_map" "greyscale" -- -field_mu_profile map -field_mu_map "$scratch/colour.png"
s "-field_mu_map" "cannot open" -- -field_mu_profile map -field_mu_map "$scratch/missing.h5"
s "-field_mu_map" ".png (greyscale image)" -- -field_mu_profile map -field_mu_map "$scratch/map.txt"
s "-field_mu_map_extent" "covers the plate" -- -field_mu_profile map -field_mu_map "$source_dir/input/fields/pillars.png" -field_mu_map_extent 0,1e-3,0,5e-3
s "-field_mu_map_range" "two values" -- -field_mu_profile map -field_mu_map "$source_dir/input/fields/pillars.png" -field_mu_map_range 1
# An E field along y is taken by the spring-block model (per-block stiffness) and checked block by block.
s "-field_E_delta = 1.5" "E > 0 [Pa] everywhere on the plate" "E = -" "y = 2.08333e-05 m" -- -field_E_profile linear -field_E_delta 1.5 -field_E_angle 90
s "-field_E_delta = -1.2" "E > 0 [Pa] everywhere on the plate" -- -field_E_profile linear -field_E_delta -1.2 -field_E_centre 2.5e-3,2.5e-3
# Options that cannot work together or would be ignored.
s "-field_E_profile = linear" "-grading_property" -- -grading_profile linear -grading_delta 0.2 -field_E_profile linear
s "-field_mu_profile = none" "-field_mu_delta" -- -field_mu_delta 0.2
s "-field_mu_s_profile" "-field_mu_profile" -- -field_mu_profile constant -field_mu_s_profile constant
s "-field_mu_period = 0" "> 0 [m]" -- -field_mu_profile stripes -field_mu_delta 0.2
s "-field_mu_duty = 1" "0 < duty < 1" -- -field_mu_profile stripes -field_mu_period 1e-3 -field_mu_duty 1
s "-field_E_bands = 1" "0 (continuous) or 2..4096" -- -field_E_profile linear -field_E_bands 1
s "-field_mu_centre" "two values" -- -field_mu_profile linear -field_mu_centre 1e-3
s "-field_mu_deltaa" -- -field_mu_profile linear -field_mu_deltaa 0.2
# The FEM refuses the same way (its sites: cell centres of its mesh).
expect 1 "$fem" -output "-field_E_delta = 1.5" "E > 0" -- -fem_nx 4 -fem_ny 4 -fem_nz 1 -field_E_profile linear -field_E_delta 1.5 -field_E_angle 90
expect 1 "$fem" -output "-field_mu_map" "finite values" -- -fem_nx 4 -fem_ny 4 -fem_nz 1 -field_mu_profile map -field_mu_map "$scratch/nan.h5"
# On a mesh graded toward the edges, at the cells of that mesh: E = 1 - 1.02 (1 - 2u) is positive at
# the first centre of 30 equal cells (u = 1/60) but not at the first graded cell's (x = 31.5 um).
expect 1 "$fem" -output "-field_E_delta = 1.02" "E > 0" "x = 3.15394e-05 m" -- -fem_nx 30 -fem_ny 30 -fem_nz 1 -fem_edge_ratio 4 -fem_edge_band 1e-3 -field_E_profile linear -field_E_delta 1.02
# Every rank refuses (no hang, no file).
expect 2 "$sbm" -output "-field_mu_map" "finite values" -- -field_mu_profile map -field_mu_map "$scratch/nan.h5"
expect 2 "$sbm" -output "-field_p_delta = -1.2" -- -field_p_profile step -field_p_delta -1.2 -field_p_position 1e-3
expect 2 "$fem" -output "-field_mu_k_delta = 0.8" -- -fem_nx 4 -fem_ny 4 -fem_nz 1 -field_mu_k_profile constant -field_mu_k_delta 0.8

if [ $failures -ne 0 ]; then echo "$failures refusal(s) wrong"; exit 1; fi
echo "all refusals correct"
