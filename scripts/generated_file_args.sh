# Sourced by the scripts that write a generated file (regenerate_docs_tables.sh, scene_bars.sh):
# their arguments [build-dir] [--check] as $build (default: the checkout's build/) and $check (1:
# compare only). $here is the checkout.
build=$here/build
check=0
for arg in "$@"; do
  case $arg in --check) check=1 ;; *) build=$arg ;; esac
done
