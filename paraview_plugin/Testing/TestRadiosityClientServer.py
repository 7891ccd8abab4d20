"""pvpython test of the plugin against `mpirun -np 2 pvserver`, as a user of
ParaView's client-server mode runs it:
`pvpython TestRadiosityClientServer.py <plugin.so> <mpirun> <pvserver> <reference.json> <out dir>`
where reference.json is paraview.TestRadiosityMPI-np1's one-process answer.

The script starts the two server ranks itself (on a free port), connects,
loads the plugin on both sides, and:
- solves the Cornell Box source (held by server rank 0, rank 1 empty) and
  the same after RedistributeDataSet, each fetched whole to the client: the
  peak and total irradiance must equal one process's (1e-12 relative);
- shows the redistributed box in the Radiosity Render View rendered on the
  servers (remote rendering: the client solves nothing and shows their
  image): the screenshot must equal one process's (mean pixel difference
  0.5 at most);
- prints no error on the client.
"""
import json
import os
import socket
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from radiosity_pvtest import CapturedMessages, check, cornell_view_screenshot, finish, read_png  # noqa: E402

plugin, mpirun, pvserver, reference_path, out_dir = sys.argv[1:6]
reference = json.load(open(reference_path))

with socket.socket() as s:
    s.bind(("localhost", 0))
    port = s.getsockname()[1]
# Without this process's own MPI singleton's variables (pvpython initialises
# MPI): an mpirun started with them does not start the servers.
env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PRTE_"))}
env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
server = subprocess.Popen([mpirun, "-np", "2", pvserver, "--force-offscreen-rendering",
                           "--server-port=%d" % port], env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
try:
    # The server prints "Accepting connection(s)" once it listens.
    deadline = time.time() + 120
    started = []
    for line in server.stdout:
        started.append(line)
        if "Accepting connection" in line or time.time() > deadline:
            break
    if not any("Accepting connection" in line for line in started):
        print("the servers did not start:\n" + "".join(started))
        check(False, "mpirun -np 2 pvserver did not start")
        finish()
    # Keep reading what the server prints, so that a full pipe never stops it.
    threading.Thread(target=lambda: [None for _ in server.stdout], daemon=True).start()
    Connect("localhost", port)
    LoadPlugin(plugin, remote=False, ns=globals())
    LoadPlugin(plugin, remote=True, ns=globals())
    results = {}
    with CapturedMessages() as messages:
        box = CornellBox()
        redistributed = RedistributeDataSet(Input=box)
        for name, source in (("source", box), ("redistributed", redistributed)):
            solve = Radiosity(Input=source)
            solve.Tolerance = 0.01
            data = servermanager.Fetch(solve)
            cells = data.GetCellData().GetArray("Irradiance")
            peak = max(sum(cells.GetComponent(c, k) for k in range(3)) / 3.0
                       for c in range(data.GetNumberOfCells())) if cells else 0.0
            results[name] = {"elements": data.GetNumberOfCells(), "peak": peak}
        image = os.path.join(out_dir, "TestRadiosityClientServer.png")
        cornell_view_screenshot(redistributed, image, remote_rendering=True)
    print(messages.text)
    check("ERR" not in messages.text and "Error" not in messages.text,
          "errors were printed on the client: %s" % messages.text[:2000])
    for name in ("source", "redistributed"):
        one, many = reference[name]["peak"], results[name]["peak"]
        difference = abs(many - one) / abs(one)
        print("%s: %d elements (one process %d), peak %.9g (one process %.9g), relative difference %.3g"
              % (name, results[name]["elements"], reference[name]["elements"], many, one, difference))
        check(results[name]["elements"] == reference[name]["elements"], "%s: elements differ" % name)
        check(difference <= 1e-12, "%s: peak differs by %.3g (bound 1e-12)" % (name, difference))
    mine, theirs = read_png(image), read_png(reference["view_redistributed"])
    difference = abs(mine - theirs).mean() if mine.shape == theirs.shape else float("inf")
    print("view: mean pixel difference %.4f against one process" % difference)
    check(difference <= 0.5, "the view's image differs from one process's: %.4f" % difference)
finally:
    server.terminate()
    try:
        server.wait(timeout=20)
    except subprocess.TimeoutExpired:
        server.kill()
finish()
