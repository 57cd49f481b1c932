"""The CI steps of the docs, the wheel, the type check and the notebook fail when broken.

Each test breaks one on purpose, on a tiny input, and checks that the very tool .ci/run
uses refuses it: a documentation page with a reference to a surfmet name that does not
exist, a gallery example that raises, a wheel missing a bundled scan, a type error in a
checked module, a notebook cell that raises.
"""

from __future__ import annotations

import importlib.util
import subprocess
import sys
import textwrap
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
CI = ROOT / ".ci"

pytestmark = pytest.mark.slow


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _sphinx(src: Path, out: Path) -> subprocess.CompletedProcess[str]:
    """The docs build of .ci/run (warnings as errors) on a tiny project."""
    return subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b",
                           "html", str(src), str(out)], capture_output=True, text=True,
                          cwd=src, timeout=300)


def _tiny_project(tmp_path: Path, page: str, extra_conf: str = "") -> Path:
    src = tmp_path / "src"
    src.mkdir(parents=True)
    (src / "conf.py").write_text(textwrap.dedent(f"""\
        import sys
        sys.path.insert(0, {str(ROOT)!r})
        sys.path.insert(0, {str(ROOT / "docs" / "_ext")!r})
        extensions = ["sphinx.ext.autodoc", "surfmet_xref"]
        nitpicky = True
        nitpick_ignore_regex = [(r"py:.*", r"^(?!(surfmet|contact|profiles)\\b).*")]
        """) + extra_conf)
    (src / "index.rst").write_text(page)
    return src


def test_docs_build_fails_on_a_broken_reference(tmp_path):
    pytest.importorskip("sphinx")
    page = ("Title\n=====\n\n:func:`surfmet.read`, :func:`contact._rolling.sphere_sweep` "
            "and :class:`profiles._scales.Scan` name real objects.\n")
    good = _sphinx(_tiny_project(tmp_path / "good", page), tmp_path / "good" / "out")
    assert good.returncode == 0, good.stderr
    broken = page + "\n:func:`surfmet.read_everything` names nothing.\n"
    bad = _sphinx(_tiny_project(tmp_path / "bad", broken), tmp_path / "bad" / "out")
    assert bad.returncode != 0
    assert "surfmet.read_everything" in bad.stderr
    assert "surfmet.read`" not in bad.stderr and "sphere_sweep" not in bad.stderr


def test_docs_build_fails_on_an_example_that_raises(tmp_path):
    pytest.importorskip("sphinx_gallery")
    examples = tmp_path / "examples"
    examples.mkdir()
    (examples / "README.txt").write_text("Gallery\n=======\n")
    (examples / "plot_broken.py").write_text(
        '"""\nA broken example\n================\n\nIt raises.\n"""\n\n'
        'raise RuntimeError("this example is broken on purpose")\n')
    conf = textwrap.dedent(f"""\
        extensions.append("sphinx_gallery.gen_gallery")
        sphinx_gallery_conf = {{"examples_dirs": [{str(examples)!r}],
                               "gallery_dirs": ["auto_examples"],
                               "filename_pattern": r"/plot_"}}
        """)
    page = "Title\n=====\n\n.. toctree::\n\n   auto_examples/index\n"
    src = _tiny_project(tmp_path, page, conf)
    run = _sphinx(src, tmp_path / "out")
    assert run.returncode != 0
    assert "plot_broken.py" in run.stdout + run.stderr
    assert "broken on purpose" in run.stdout + run.stderr


def test_wheel_check_names_a_missing_data_file(tmp_path):
    check = _load("check_wheel", CI / "check_wheel.py")
    tracked = subprocess.run(["git", "ls-files", *check.PACKAGES], cwd=ROOT, check=True,
                             capture_output=True, text=True).stdout.split()
    assert "surfmet/data/paper_plate.x3p" in tracked
    assert "rotor/verdict_calibration.json" in tracked
    wheel = tmp_path / "surfmet-0-py3-none-any.whl"
    left_out = {"surfmet/data/paper_plate.x3p", "rotor/verdict_calibration.json"}
    with zipfile.ZipFile(wheel, "w") as z:
        for name in tracked:
            if name not in left_out:
                z.writestr(name, b"")
    assert check.missing_from_wheel(wheel) == sorted(left_out)
    assert check.main([str(wheel)]) == 1
    with zipfile.ZipFile(wheel, "a") as z:
        for name in left_out:
            z.writestr(name, b"")
    assert check.main([str(wheel)]) == 0


def test_type_check_fails_on_a_type_error(tmp_path):
    pytest.importorskip("mypy")
    bad = tmp_path / "broken_module.py"
    bad.write_text("def area(radius: float) -> float:\n    return 'pi r^2'\n")
    run = subprocess.run([sys.executable, "-m", "mypy", "--config-file",
                          str(ROOT / "pyproject.toml"), str(bad)],
                         capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "broken_module.py:2: error: Incompatible return value type" in run.stdout


def test_notebook_run_fails_on_a_cell_that_raises(tmp_path, capsys):
    nbformat = pytest.importorskip("nbformat")
    pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("x = 1"),
                nbformat.v4.new_code_cell("raise ValueError('broken on purpose')")]
    path = tmp_path / "broken.ipynb"
    nbformat.write(nb, path)
    runner = _load("run_notebooks", CI / "run_notebooks.py")
    assert runner.main([str(path)]) == 1
    err = capsys.readouterr().err
    assert "broken.ipynb: a cell raised" in err and "broken on purpose" in err
