"""An online study's server for remote participants, made from a study file and `haven serve`'s
options (the command and api.serve_study)."""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path
from typing import Any

from haven_scenarios.record.progress import bind
from haven_scenarios.run.domains import DomainBusy, domains_of, parse_domains
from haven_scenarios.study.names import study_dir
from haven_scenarios.study.protocol import load_study
from haven_scenarios.web.study_server import ServeOptions, StudyServer
from haven_scenarios.web.tls import tls_files


def open_server(
    study: str,
    dir: Path | None = None,
    tls_cert: str | None = None,
    tls_key: str | None = None,
    params_file: str | None = None,
    **options: Any,
) -> StudyServer:
    """`haven serve`'s server for a study file or a shipped study, not started yet (`options`:
    ServeOptions' host, port, capacity, trial_ports, id_param, on_disconnect, reconnect_timeout,
    network, domains). ValueError (one line) for a bad study or option; OSError when its folder cannot be written."""
    s = load_study(study)
    root = study_dir(dir, s).resolve()
    trials = bind(s, root)
    if isinstance(options.get("domains"), str):  # (the Python API's "30-39")
        options["domains"] = parse_domains(options["domains"])
    o = ServeOptions(str(Path(s.source).resolve()), root, **options)
    if o.trial_ports and o.trial_ports[1] - o.trial_ports[0] + 1 < o.capacity:
        raise ValueError(
            f"--trial-ports: {o.trial_ports[0]}-{o.trial_ports[1]} has fewer ports than --capacity {o.capacity}"
        )
    try:  # (each participant's runner takes a domain of its own in the range: checked once, here)
        domains = o.domains or domains_of(os.environ)
    except DomainBusy as e:
        raise ValueError(str(e)) from None
    if domains is not None and len(domains.ids) < o.capacity:
        raise ValueError(
            f"{domains}: fewer ROS domains than --capacity {o.capacity} (each participant's trial takes one)"
        )
    o = replace(
        o, tls=tls_files(tls_cert, tls_key), params_file=str(Path(params_file).resolve()) if params_file else None
    )
    return StudyServer(o, s, trials)
