"""The bindings' README as written (issue 24 item 5): its Python blocks, in
order, are one program run from a folder that looks like the repository
root (scenarios/ linked in), so a renamed call, property or field breaks
this test rather than a reader. Registered as its own CTest test,
python_bindings.readme."""

import os
import re
import subprocess
import sys
from pathlib import Path

README = Path(__file__).resolve().parents[1] / "README.md"
SOURCE = Path(__file__).resolve().parents[3]


def python_blocks(text):
    return re.findall(r"^```python\n(.*?)^```$", text, re.S | re.M)


def test_readme_has_the_blocks_a_reader_needs():
    blocks = python_blocks(README.read_text())
    program = "\n".join(blocks)
    for call in ("eoir.Engine(", ".point_at(", ".track(", ".truth(", "eoir.Kind.", "eoir.Scenario.load(",
                 "sweep.run_dask("):
        assert call in program, call
    assert len(blocks) >= 7


def test_readme_python_blocks_run_as_written(tmp_path):
    program = "\n".join(python_blocks(README.read_text()))
    (tmp_path / "readme_program.py").write_text(program)
    os.symlink(SOURCE / "scenarios", tmp_path / "scenarios")
    # -c with exec: the program is __main__ without a file, so Dask's spawned
    # workers do not run it again.
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(README.parent)] + [
        os.path.abspath(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]))
    out = subprocess.run([sys.executable, "-c", "exec(compile(open('readme_program.py').read(), "
                          "'README.md', 'exec'))"], cwd=tmp_path, env=env, capture_output=True, text=True,
                         timeout=600)
    print(out.stdout[-4000:])
    assert out.returncode == 0, out.stderr[-4000:]
    assert "EOIR_ERR_OUT_OF_RANGE" in out.stdout          # the error block printed what it says
    assert (tmp_path / "scenario.scd").is_file() and (tmp_path / "sensor.json").is_file()
    assert list(tmp_path.glob("wide_*.fits"))
