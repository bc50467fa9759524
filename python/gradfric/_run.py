"""gradfric.run: one scene through a driver under mpiexec, its results file read by gradfric.open."""
import os
import re
import shutil
import subprocess
import tempfile

DRIVERS = ("gradfric", "gradfric-fem", "gradfric-study", "gradfric-design", "gradfric-calibrate")
_HERE = os.path.dirname(os.path.abspath(__file__))


class RunError(RuntimeError):
    """A driver run that failed: message (the driver's `<driver>: error: ...` line, or the last line
    it printed), returncode (2: bad input, docs/running.md "Bad input"), command, stdout, stderr."""

    def __init__(self, message, returncode, command, stdout="", stderr=""):
        super().__init__(f"{message} (exit code {returncode})")
        self.message, self.returncode, self.command = message, returncode, command
        self.stdout, self.stderr = stdout, stderr


def driver_folders():
    """Where run() looks for a driver, in this order: $GRADFRIC_BIN; the build tree of the checkout
    the package is used from (python/gradfric -> build/drivers); the install prefix's bin
    (P/share/gradfric/python/gradfric -> P/bin); then PATH (find_driver)."""
    folders = []
    if os.environ.get("GRADFRIC_BIN"):
        folders.append(os.environ["GRADFRIC_BIN"])
    folders.append(os.path.normpath(os.path.join(_HERE, "..", "..", "build", "drivers")))
    folders.append(os.path.normpath(os.path.join(_HERE, "..", "..", "..", "..", "bin")))
    return folders


def find_driver(driver="gradfric"):
    """The path of a driver: driver itself if it names a file (has a '/'), else the first
    executable of that name in driver_folders(), else on PATH. FileNotFoundError if none."""
    if os.sep in driver:
        if os.access(driver, os.X_OK):
            return os.path.abspath(driver)
        raise FileNotFoundError(f"gradfric.run: {driver} is not an executable file")
    if driver not in DRIVERS:
        raise ValueError(f"gradfric.run: unknown driver {driver!r} (one of {', '.join(DRIVERS)})")
    folders = driver_folders()
    if os.environ.get("GRADFRIC_BIN"):  # an explicit folder is the only one looked at
        folders = folders[:1]
    for folder in folders:
        candidate = os.path.join(folder, driver)
        if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    found = None if os.environ.get("GRADFRIC_BIN") else shutil.which(driver)
    if found:
        return found
    raise FileNotFoundError(f"gradfric.run: no {driver} in {os.pathsep.join(folders)}"
                            + ("" if os.environ.get("GRADFRIC_BIN") else " nor on PATH")
                            + " (set GRADFRIC_BIN to the folder of the drivers)")


def option_arguments(options):
    """{name: value} as driver arguments: -name value; True: -name alone; False: -name false;
    None: left out; a list or tuple: its items comma-joined."""
    args = []
    for name, value in options.items():
        if value is None:
            continue
        flag = "-" + name.lstrip("-")
        if value is True:
            args.append(flag)
        elif value is False:
            args += [flag, "false"]
        elif isinstance(value, (list, tuple)) or (hasattr(value, "ndim") and getattr(value, "ndim", 0) > 0):
            args += [flag, ",".join(_text(v) for v in value)]
        else:
            args += [flag, _text(value)]
    return args


def _text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if hasattr(value, "item") and not isinstance(value, (str, bytes)):  # numpy scalars
        value = value.item()
    return repr(value) if isinstance(value, float) else str(value)


def _error_line(driver, stdout, stderr):
    """The driver's one-line error (`gradfric: error: ...`), else the last line it printed that is
    not mpiexec's."""
    name = re.escape(os.path.basename(driver))
    for text in (stderr, stdout):
        match = re.search(rf"^{name}: error: .*$", text, re.M)
        if match:
            return match.group(0).strip()
    for text in (stderr, stdout):
        lines = [line.strip() for line in text.splitlines() if line.strip() and not line.startswith("---")
                 and "mpiexec" not in line and "Primary job" not in line]
        if lines:
            return lines[-1]
    return f"{os.path.basename(driver)} failed"


def run(options_file=None, ranks=2, driver="gradfric", output=None, *, mpiexec="mpiexec", cwd=None,
        quiet=True, **options):
    """Run one scene and return its results file read by gradfric.open (an xarray Dataset).

    options_file: a scene file (-options_file); ranks: MPI ranks (mpiexec -n ranks; None: the
    driver is run without mpiexec); driver: gradfric, gradfric-fem, gradfric-study,
    gradfric-design, gradfric-calibrate, or a path (find_driver says where it is looked for);
    output: the results file written (-output; None: a temporary folder, removed when the
    Dataset is closed); mpiexec: the launcher, a str or a list (["mpiexec", "--oversubscribe"]);
    cwd: the folder the driver runs in; quiet: False prints what the driver printed.
    **options: the driver's options without the dash: sbm_N=8 -> -sbm_N 8; True -> -name alone,
    False -> -name false, a list -> comma-joined (ensemble_delta=[0, 0.2] -> -ensemble_delta 0,0.2).
    A failed run raises RunError with the driver's one-line message and its exit code (2: bad input).
    """
    path = find_driver(driver)
    scratch = None
    if output is None:
        scratch = tempfile.mkdtemp(prefix="gradfric_run_")
        extension = ".opts" if os.path.basename(path).startswith("gradfric-calibrate") else ".h5"
        output = os.path.join(scratch, "results" + extension)
    output = os.path.abspath(os.fspath(output))
    command = [path]
    if options_file is not None:
        command += ["-options_file", os.path.abspath(os.fspath(options_file))]
    command += option_arguments(options) + ["-output", output]
    if ranks is not None:
        launcher = [mpiexec] if isinstance(mpiexec, str) else list(mpiexec)
        command = launcher + ["-n", str(int(ranks))] + command
    # Open MPI refuses to run as root without these (as the repository's scripts); harmless otherwise.
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    try:
        done = subprocess.run(command, env=env, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, text=True)
        if not quiet:
            print(done.stdout, end="")
            print(done.stderr, end="")
        if done.returncode != 0:
            raise RunError(_error_line(path, done.stdout, done.stderr), done.returncode, command,
                           done.stdout, done.stderr)
        from . import open as open_results
        ds = open_results(output)
    except BaseException:
        if scratch:
            shutil.rmtree(scratch, ignore_errors=True)
        raise
    if scratch:
        close = getattr(ds, "_close", None)

        def close_and_remove():
            try:
                if close is not None:
                    close()
            finally:
                shutil.rmtree(scratch, ignore_errors=True)
        ds.set_close(close_and_remove)
    return ds
