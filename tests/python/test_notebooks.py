"""The course's notebooks (docs/notebooks) run headless in their quick mode, each ending in the
check cell that judges its result; a failed check fails the test.  Needs Debian's
python3-nbclient and python3-ipykernel (skipped without them).  The kernel runs this
interpreter, with the package from this tree."""
import glob
import json
import os
import sys

import pytest

from conftest import ROOT

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")
pytest.importorskip("matplotlib")

NOTEBOOKS = sorted(glob.glob(os.path.join(ROOT, "docs", "notebooks", "*.ipynb")))


@pytest.fixture(scope="module")
def kernel_env(tmp_path_factory):
    """A kernel spec for this interpreter (the python3 spec may name another one) and the
    environment of the quick mode, figures into a scratch folder."""
    d = tmp_path_factory.mktemp("jupyter")
    spec = d / "kernels" / "hcbd-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "hcbd test", "language": "python"}))
    env = {"JUPYTER_PATH": str(d), "HCBD_QUICK": "1", "HCBD_FIGDIR": str(d), "MPLBACKEND": "Agg",
           "PYTHONPATH": os.pathsep.join([os.path.join(ROOT, "python"), os.environ.get("PYTHONPATH", "")]),
           "OMP_NUM_THREADS": "1"}
    saved = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    yield d
    for k, v in saved.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v


def run(nb, cwd):
    nbclient.NotebookClient(nb, timeout=300, kernel_name="hcbd-test",
                            resources={"metadata": {"path": cwd}}).execute()
    return nb


def test_notebooks_all_there():
    """Ten notebooks, one per exercise of docs/exercises.md, each ending in a check cell."""
    assert len(NOTEBOOKS) == 10, [os.path.basename(p) for p in NOTEBOOKS]
    for path in NOTEBOOKS:
        nb = nbformat.read(path, as_version=4)
        last = [c for c in nb.cells if c.cell_type == "code"][-1].source
        assert "assert" in last and "QUICK" in "".join(c.source for c in nb.cells), path


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[os.path.basename(p)[:-6] for p in NOTEBOOKS])
def test_notebook(path, kernel_env):
    nb = run(nbformat.read(path, as_version=4), os.path.dirname(path))
    out = "".join(o.get("text", "") for o in nb.cells[-1].outputs)
    assert "OK" in out, out


def test_notebook_check_fails(kernel_env, tmp_path):
    """A check cell that does not hold stops the run, so a notebook that reads wrong fails."""
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("import hcbd\nw = hcbd.World(N=64, seed=1)\nw.step(10)"),
                nbformat.v4.new_code_cell("assert abs(w.temperature() - 7) < 0.01, 'outside'")]
    with pytest.raises(nbclient.exceptions.CellExecutionError):
        run(nb, str(tmp_path))
