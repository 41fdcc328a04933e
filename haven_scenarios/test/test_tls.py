"""HTTPS for the pages (web/tls.py, `haven cert`, `--tls-cert/--tls-key`): the certificate `haven
cert` makes is checked by a client we did not write (the standard library's OpenSSL, trusting only
the lab's authority, host names checked), the pages and a WebSocket pass through TLS whole, and
bad files are one line."""

from __future__ import annotations

import ssl
import stat
import urllib.error
import urllib.request
from pathlib import Path

import pytest
from cryptography import x509

from haven_scenarios.tools.cli import main
from haven_scenarios.web.access import role_token
from haven_scenarios.web.editor_server import EditorServer
from haven_scenarios.web.front_door import FrontDoor
from haven_scenarios.web.tls import (
    CA_CERT,
    CA_KEY,
    SERVER_CERT,
    SERVER_KEY,
    address_notes,
    make_certificates,
    names_of,
    server_context,
    tls_files,
)

pytestmark = pytest.mark.integration  # (TLS servers and clients on sockets)


@pytest.fixture(scope="module")
def certs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("tls")
    assert main(["cert", "--dir", str(folder)]) == 0  # this machine's names and addresses, localhost among them
    return folder


def served(certs: Path, tmp_path: Path) -> EditorServer:
    server = EditorServer(
        "127.0.0.1", 0, {"name": "w", "walls": []}, tmp_path, server_context(certs / SERVER_CERT, certs / SERVER_KEY)
    )
    server.start()
    return server


def test_haven_cert_makes_the_authority_once_and_keeps_the_keys_private(
    certs: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    for key in (CA_KEY, SERVER_KEY):
        assert stat.S_IMODE((certs / key).stat().st_mode) == 0o600, key
    before = (certs / CA_CERT).read_bytes()
    assert main(["cert", "--dir", str(certs), "--name", "lab-pc.local"]) == 0
    out = capsys.readouterr().out
    assert "authority (kept)" in out and "--tls-cert" in out, out
    assert (certs / CA_CERT).read_bytes() == before  # headsets that trust it go on trusting the next certificate
    leaf = x509.load_pem_x509_certificates((certs / SERVER_CERT).read_bytes())[0]
    leaf.verify_directly_issued_by(x509.load_pem_x509_certificate(before))  # signed by the same, kept authority
    # --name adds to this machine's
    assert {"localhost", "127.0.0.1", "lab-pc.local"} <= set(names_of(certs / SERVER_CERT))
    assert main(["cert", "--dir", str(certs), "--name", "bad name"]) == 2
    assert "is neither a host name" in capsys.readouterr().err


def test_haven_cert_refuses_a_symlinked_key_path_leaving_its_target_untouched(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("the researcher's notes\n")
    victim.chmod(0o644)
    for key in (CA_KEY, SERVER_KEY):  # a new authority's key, and the server key beside a kept authority
        folder = tmp_path / key
        if key == SERVER_KEY:
            assert main(["cert", "--dir", str(folder)]) == 0
        (folder / key).unlink(missing_ok=True)
        folder.mkdir(exist_ok=True)
        (folder / key).symlink_to(victim)
        assert main(["cert", "--dir", str(folder)]) == 2
        err = capsys.readouterr().err.strip()
        assert err.count("\n") == 0 and f"{key} is a symbolic link: refusing to write a secret through it" in err, err
        assert victim.read_text() == "the researcher's notes\n" and stat.S_IMODE(victim.stat().st_mode) == 0o644
        assert (folder / key).is_symlink()


def test_a_client_trusting_only_the_lab_authority_opens_the_page_and_the_cookie_is_secure(
    certs: Path, tmp_path: Path
) -> None:
    server = served(certs, tmp_path)
    try:
        assert server.url.startswith("https://localhost:"), server.url
        trusting = ssl.create_default_context(cafile=certs / CA_CERT)  # host names checked, as browsers do
        for url in (server.url, server.url.replace("localhost", "127.0.0.1")):
            with urllib.request.urlopen(url, context=trusting, timeout=30) as r:
                assert r.status == 200
                assert "Secure" in r.headers["Set-Cookie"] and "HttpOnly" in r.headers["Set-Cookie"]
                assert (
                    r.headers["X-Content-Type-Options"] == "nosniff" and r.headers["Referrer-Policy"] == "same-origin"
                )
                assert "script-src 'self';" in r.headers["Content-Security-Policy"]  # (the editor has no inline script)
        with pytest.raises(urllib.error.URLError, match="CERTIFICATE_VERIFY_FAILED"):  # nobody else trusts it
            urllib.request.urlopen(server.url, context=ssl.create_default_context(), timeout=30)
        plain = server.url.replace("https://", "http://")
        # no page in clear text on the same port: one line saying why
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(plain, timeout=30)
        assert refused.value.code == 400 and b"open it with https://" in refused.value.read()
    finally:
        server.stop()


def test_a_certificate_for_other_names_fails_the_host_name_check(certs: Path, tmp_path: Path) -> None:
    made = make_certificates(tmp_path / "other", ["elsewhere.example"])
    server = EditorServer("127.0.0.1", 0, {"name": "w", "walls": []}, tmp_path, server_context(made.cert, made.key))
    server.start()
    try:
        with pytest.raises(urllib.error.URLError, match=r"match|mismatch"):
            urllib.request.urlopen(server.url, context=ssl.create_default_context(cafile=made.ca_cert), timeout=30)
    finally:
        server.stop()


def test_a_websocket_is_relayed_through_the_https_front_door(certs: Path) -> None:
    from test_web import EchoBackend
    from websockets.sync.client import connect

    backend = EchoBackend()
    tls = server_context(certs / SERVER_CERT, certs / SERVER_KEY)
    door = FrontDoor("127.0.0.1", 0, "secret", {"console": backend.port}, lambda role: {}, tls=tls)
    door.start()
    try:
        assert door.base_url("127.0.0.1").startswith("https://localhost:")
        context = ssl.create_default_context(cafile=certs / CA_CERT)
        url = f"wss://localhost:{door.port}/ws/console?token={role_token('secret', 'console')}"
        with connect(url, ssl=context, subprotocols=["foxglove.sdk.v1"], open_timeout=30, max_size=None) as page:
            payload = bytes(range(256)) * 1024  # 256 KiB: many TLS records
            page.send(payload)
            assert page.recv(timeout=30) == payload.upper()
        assert backend.received[-1] == payload
    finally:
        door.stop()
        backend.close()


def test_the_researcher_is_told_when_the_printed_address_will_not_work_for_a_headset(certs: Path) -> None:
    assert address_notes("localhost", "") == []
    assert "plain http on 192.168.1.20" in address_notes("192.168.1.20", "")[0]
    assert address_notes("127.0.0.1", str(certs / SERVER_CERT)) == []
    (warning,) = address_notes("10.9.9.9", str(certs / SERVER_CERT))
    assert warning.startswith("warning: the certificate") and "does not name 10.9.9.9" in warning


def test_tls_files_that_are_wrong_are_one_line(certs: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert tls_files(None, None) is None
    with pytest.raises(ValueError, match="go together"):
        tls_files(str(certs / SERVER_CERT), None)
    with pytest.raises(ValueError, match=r"--tls-key .*: no such file"):
        tls_files(str(certs / SERVER_CERT), str(tmp_path / "missing.pem"))
    with pytest.raises(ValueError, match="not a certificate and its key"):  # another certificate's key
        server_context(certs / SERVER_CERT, certs / CA_KEY)
    not_pem = tmp_path / "notes.txt"
    not_pem.write_text("hello\n")
    with pytest.raises(ValueError, match="not a certificate and its key"):
        server_context(not_pem, certs / SERVER_KEY)
    assert main(["edit", "--port", "0", "--tls-cert", str(not_pem), "--tls-key", str(certs / SERVER_KEY)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "not a certificate and its key" in err, err
