"""The services under both the command line and the Python API: a recorded trial (its suite of
processes, its ending and outcome), a participant's run of a study, an online study's server and
the power pool."""
