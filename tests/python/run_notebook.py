"""Runs a notebook top to bottom with nbclient (as `jupyter nbconvert --execute` would) and fails
on the first cell that raises. Usage: run_notebook.py NOTEBOOK [TIMEOUT_S]. The kernel is the
interpreter running this script (its folder first on the PATH), in the current folder; the
notebook file is not changed."""
import os
import sys

import nbclient
import nbformat

notebook, timeout = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 600
# The kernel spec starts "python3" from the PATH: make it this interpreter (Debian's, with numpy).
os.environ["PATH"] = os.path.dirname(sys.executable) + os.pathsep + os.environ.get("PATH", "")
nb = nbformat.read(notebook, as_version=4)
client = nbclient.NotebookClient(nb, timeout=timeout, kernel_name="python3",
                                 resources={"metadata": {"path": os.getcwd()}})
client.execute()
outputs = sum(len(cell.get("outputs", [])) for cell in nb.cells if cell.cell_type == "code")
print(f"{notebook}: {len(nb.cells)} cells run, {outputs} outputs")
