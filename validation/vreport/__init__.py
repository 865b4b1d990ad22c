"""The validation report's code; validation/report.py is the command that drives it.

    runs.py      a Run (one `sphdem run`), its RunResult, running sphdem and the reuse rule
                 (--reuse), resuming a stopped run, --run-dir (adopt)
    rows.py      Row, its kinds (comparison, health, self-check; a comparison's reference
                 independent or the solver's own closure) and statuses (PASS, FAIL, MISS
                 with its evidence, INFO, SKIP), the safeguard rows, the table's
                 formatting, the summary count and the exit status
    figures.py   matplotlib (Agg) and Context, where a scene's figures go
    scenes/      one module per scene; scenes/__init__.py holds the registry SCENES
    matrix.py    the regime matrix (issue 14; PART where a regime is read from a stand-in
                 or a test) and the extremes matrix (issue 15)

The closed forms stay beside the package, as modules of their own: theory.py, drag_laws.py
and fluidised_bed.py (imported as top-level modules: validation/ is on sys.path).
"""
