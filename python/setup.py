"""Builds in a temporary folder: nothing is written into the checkout (no build/, no
gradfric.egg-info), and no module deleted from gradfric/ survives in a stale build/lib to be
installed again. Everything else is in pyproject.toml."""
import atexit
import shutil
import tempfile

from setuptools import setup

scratch = tempfile.mkdtemp(prefix="gradfric-build-")
atexit.register(shutil.rmtree, scratch, ignore_errors=True)
setup(options={"build": {"build_base": f"{scratch}/build"}, "egg_info": {"egg_base": scratch}})
