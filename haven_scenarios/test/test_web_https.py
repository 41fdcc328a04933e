"""A headset on the lab network, played by headless Chromium: over plain http from the LAN address
the page is an insecure context with no WebXR; over the https address `haven run --web
--tls-cert/--tls-key` prints, with the lab's authority from `haven cert` trusted (and only it: its
key's hash is the one Chromium is told to accept), the page is a secure context, `navigator.xr`
is there, and with an emulated headset (Meta's iwer) "Enter VR" is offered and enters.
Skipped, with one line, where no Chromium can be had."""

import base64
import hashlib
import os
import shutil
import subprocess

import pytest
from test_web_browser import PAGE_LOAD_MS, PAGE_TIMEOUT_MS, WEB_SOURCES, WebTrial, head_on_scenario, lan_address

from conftest import CHROMIUM_ARGS, chromium_path
from haven_scenarios.tools.cli import main as haven
from haven_scenarios.web.serving import HTML, PageServer, Routes, reply

pytestmark = [pytest.mark.ros, pytest.mark.browser]


def spki_hash(ca_pem: bytes) -> str:
    """base64(SHA-256(SubjectPublicKeyInfo)): how Chromium's --ignore-certificate-errors-spki-list
    names a key whose chains it accepts (our stand-in for a headset that trusts the authority)."""
    from cryptography import x509
    from cryptography.hazmat.primitives import serialization

    key = x509.load_pem_x509_certificate(ca_pem).public_key()
    der = key.public_bytes(serialization.Encoding.DER, serialization.PublicFormat.SubjectPublicKeyInfo)
    return base64.b64encode(hashlib.sha256(der).digest()).decode()


def blank_page(host: str) -> PageServer:
    """A page of the lab's over plain http (HAVEN's own page server, on any free port)."""
    page = b"<!doctype html><title>lab</title>"
    return PageServer("a lab page", host, 0, Routes(get={"/": lambda request: reply(request, 200, page, HTML)}))


CONTEXT = "[isSecureContext, typeof navigator.xr]"


def test_over_https_a_browser_that_trusts_the_lab_authority_is_offered_enter_vr(ros, browser, tmp_path):
    if shutil.which("node") is None or not os.path.isdir(os.path.join(WEB_SOURCES, "node_modules", "iwer")):
        pytest.skip("no Node.js or no haven_scenarios/web/node_modules to build the emulated headset: XR test skipped")
    address = lan_address() or "127.0.0.1"
    host = "0.0.0.0" if address != "127.0.0.1" else "127.0.0.1"
    certs = tmp_path / "tls"
    assert haven(["cert", "--dir", str(certs), "--name", address]) == 0
    emulator = tmp_path / "xr_emulator.js"
    subprocess.run(["node", "build.mjs", "--xr-emulator", str(emulator)], cwd=WEB_SOURCES, check=True, timeout=120)
    argv = [
        "run",
        str(head_on_scenario(tmp_path)),
        "--teleop",
        "h1",
        "--web",
        "--host",
        host,
        "--port",
        "0",
        "--sessions",
        str(tmp_path / "s"),
    ]
    trial = WebTrial(
        ros, [*argv, "--tls-cert", str(certs / "haven-server.pem"), "--tls-key", str(certs / "haven-server-key.pem")]
    )
    plain = blank_page(host)  # today's page over http from the same address, for contrast
    plain.start()
    trusted = spki_hash((certs / "haven-ca.pem").read_bytes())
    headset = browser.browser_type.launch(
        executable_path=chromium_path(), args=[*CHROMIUM_ARGS, f"--ignore-certificate-errors-spki-list={trusted}"]
    )
    try:
        url = trial.urls()["participant h1"]
        assert url.startswith(f"https://{address}:"), url
        page = headset.new_page()
        page.goto(f"http://{address}:{plain.port}/", timeout=PAGE_LOAD_MS)
        if address != "127.0.0.1":  # (loopback counts as secure even over http)
            assert page.evaluate(CONTEXT) == [False, "undefined"]  # why a headset never offered Enter VR
        page.goto(url, timeout=PAGE_LOAD_MS)
        assert page.evaluate(CONTEXT) == [True, "object"]  # the browser's own WebXR, no emulator
        page.close()
        context = headset.new_context(viewport={"width": 480, "height": 270})
        context.add_init_script(path=str(emulator))
        page = context.new_page()
        page.goto(url, timeout=PAGE_LOAD_MS)
        page.wait_for_function(
            "s => (s = window.havenState) && s.world > 0 && s.pose "
            "&& s.xrOffered && s.trial && s.trial.state === 'held'",
            timeout=PAGE_TIMEOUT_MS,
        )  # the scene and the trial over wss:// through the front door
        page.click("#start")
        page.wait_for_function("() => havenState.trial.state === 'running'", timeout=PAGE_TIMEOUT_MS)
        page.click("#enter-vr")
        page.wait_for_function("() => havenState.xr === true", timeout=PAGE_TIMEOUT_MS)
        frames = page.evaluate("havenState.frames")
        page.wait_for_function(f"() => havenState.frames > {frames + 3}", timeout=PAGE_TIMEOUT_MS)
    finally:
        headset.close()
        plain.stop()
