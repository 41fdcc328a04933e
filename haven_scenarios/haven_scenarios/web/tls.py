"""HTTPS for the study's pages: a lab's own certificate authority, a certificate for the study PC,
and the server side of TLS.

Browsers treat a page from `http://<LAN address>` as an insecure context: no `navigator.xr`, so a
headset's browser never offers "Enter VR", and the tokens travel in clear text. Served over HTTPS
with a certificate the headset trusts, the same page is a secure context. `haven cert` makes the
lab's certificate authority once (its key never leaves the study PC) and a certificate for this
machine's names and addresses signed by it; a headset or laptop trusts the authority once
(docs/howto/https.md) and then every certificate the lab makes. The cryptography is the
`cryptography` library's (X.509 from its `x509` builder, keys ECDSA P-256); the server side is the
standard library's `ssl`.
"""

from __future__ import annotations

import datetime
import ipaddress
import os
import re
import socket
import ssl
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from cryptography import x509
from cryptography.hazmat.primitives import hashes, serialization
from cryptography.hazmat.primitives.asymmetric import ec
from cryptography.x509.oid import ExtendedKeyUsageOID, NameOID

from haven_sim.common.atomic import refuse_link, write_secret

CA_CERT, CA_KEY = "haven-ca.pem", "haven-ca-key.pem"
# (made again each time: the names may have changed)
SERVER_CERT, SERVER_KEY = "haven-server.pem", "haven-server-key.pem"
CA_DAYS = 3650  # the lab's authority: ten years (a headset trusts it once)
# A server certificate's lifetime: at most 398 days, the limit Chrome and Safari enforce for
# certificates (Apple, "About upcoming limits on trusted certificates", 2020; CA/Browser Forum
# ballot SC22). Our authority is a private one, but a browser may apply it to it too.
SERVER_DAYS = 397


def server_context(cert: str | os.PathLike[str], key: str | os.PathLike[str]) -> ssl.SSLContext:
    """The TLS server context for a certificate (PEM, with its chain if any) and its key; ValueError
    in one line naming the file that is wrong."""
    for what, path in (("--tls-cert", cert), ("--tls-key", key)):
        if not Path(path).is_file():
            raise ValueError(f"{what} {path}: no such file")
    context = ssl.SSLContext(ssl.PROTOCOL_TLS_SERVER)
    context.minimum_version = ssl.TLSVersion.TLSv1_2
    try:
        context.load_cert_chain(cert, key)
    except ssl.SSLError as e:
        raise ValueError(
            f"--tls-cert {cert} / --tls-key {key}: not a certificate and its key in PEM ({e.reason or e})"
        ) from None
    return context


def tls_files(cert: str | None, key: str | None) -> tuple[str, str] | None:
    """`--tls-cert`/`--tls-key` checked (both or neither, a certificate and its key): their absolute
    paths, or None for plain HTTP; ValueError in one line otherwise."""
    if not cert and not key:
        return None
    if not (cert and key):
        raise ValueError("--tls-cert and --tls-key go together (`haven cert` makes both)")
    server_context(cert, key)
    return str(Path(cert).resolve()), str(Path(key).resolve())


def address_notes(shown: str, cert: str) -> list[str]:
    """What to tell the researcher about the address the pages are printed with (`shown`): served
    without a certificate beyond this machine, a browser treats them as insecure; with one that does
    not name the address, it refuses them."""
    if not cert:
        if shown in ("localhost", "127.0.0.1", "::1"):
            return []
        return [
            f"plain http on {shown}: browsers on other devices treat the pages as insecure (no Enter VR) "
            "and the tokens travel in clear text; serve HTTPS (haven cert, then --tls-cert and --tls-key)"
        ]
    if shown in names_of(cert):
        return []
    return [
        f"warning: the certificate {cert} does not name {shown}: "
        "browsers will refuse the pages; run haven cert again (docs/howto/https.md)"
    ]


def this_machines_names() -> list[str]:
    """The names another device may reach this machine by: localhost, the loopback addresses, the
    host name (and its .local mDNS name) and the address other machines see."""
    from haven_scenarios.web.front_door import address_for_others

    host = socket.gethostname()
    names = ["localhost", "127.0.0.1", "::1", host, f"{host}.local", address_for_others("0.0.0.0")]
    return list(dict.fromkeys(n for n in names if n))


@dataclass(frozen=True)
class Made:
    """What `make_certificates` wrote (paths) and whether the authority was new."""

    ca_cert: Path
    cert: Path
    key: Path
    new_ca: bool


def make_certificates(folder: Path, names: Sequence[str], now: datetime.datetime | None = None) -> Made:
    """In `folder`: the authority (made once; kept if there) and a certificate for `names` (host
        names or IP addresses) signed by it, with its key. Keys are written readable by their owner
    only (haven_sim/common/atomic.py: write_secret); a symbolic link in place of any of the four
    files is refused (OSError, one line) before anything is written, its target untouched."""
    from cryptography import x509
    from cryptography.hazmat.primitives import serialization
    from cryptography.hazmat.primitives.asymmetric import ec

    if not names:
        raise ValueError("haven cert: no name or address to certify")
    bad = [n for n in names if not _nameable(n)]
    if bad:
        raise ValueError(
            f"haven cert: --name {bad[0]!r} is neither a host name (letters, digits, '-', dots) nor an IP address"
        )
    folder.mkdir(parents=True, exist_ok=True)
    # (before anything is made: a link's target is never written)
    for name in (CA_CERT, CA_KEY, SERVER_CERT, SERVER_KEY):
        refuse_link(folder / name)
    now = now or datetime.datetime.now(datetime.UTC)
    ca_cert_path, ca_key_path = folder / CA_CERT, folder / CA_KEY
    new_ca = not (ca_cert_path.is_file() and ca_key_path.is_file())
    if new_ca:
        ca_key = ec.generate_private_key(ec.SECP256R1())
        ca_cert = _authority(ca_key, now)
        _write_key(ca_key_path, ca_key)
        write_secret(ca_cert_path, ca_cert.public_bytes(serialization.Encoding.PEM), mode=0o644)
    else:
        try:
            loaded = serialization.load_pem_private_key(ca_key_path.read_bytes(), password=None)
            ca_cert = x509.load_pem_x509_certificate(ca_cert_path.read_bytes())
        except ValueError as e:
            raise ValueError(f"{ca_cert_path} / {ca_key_path}: not the authority haven cert made ({e})") from None
        if not isinstance(loaded, ec.EllipticCurvePrivateKey):
            raise ValueError(f"{ca_key_path}: not the authority's EC key haven cert made")
        ca_key = loaded
    key = ec.generate_private_key(ec.SECP256R1())
    cert = _server(key, ca_key, ca_cert, names, now)
    cert_path, key_path = folder / SERVER_CERT, folder / SERVER_KEY
    _write_key(key_path, key)
    chain = cert.public_bytes(serialization.Encoding.PEM) + ca_cert.public_bytes(serialization.Encoding.PEM)
    write_secret(cert_path, chain, mode=0o644)  # the chain: a client that has the authority checks it either way
    return Made(ca_cert_path, cert_path, key_path, new_ca)


def _authority(key: ec.EllipticCurvePrivateKey, now: datetime.datetime) -> x509.Certificate:
    name = x509.Name(
        [
            x509.NameAttribute(NameOID.ORGANIZATION_NAME, "HAVEN study lab"),
            x509.NameAttribute(NameOID.COMMON_NAME, f"HAVEN lab authority ({socket.gethostname()})"),
        ]
    )
    ski = x509.SubjectKeyIdentifier.from_public_key(key.public_key())
    return (
        x509.CertificateBuilder()
        .subject_name(name)
        .issuer_name(name)
        .public_key(key.public_key())
        .serial_number(x509.random_serial_number())
        .not_valid_before(now - datetime.timedelta(minutes=5))
        .not_valid_after(now + datetime.timedelta(days=CA_DAYS))
        .add_extension(x509.BasicConstraints(ca=True, path_length=0), critical=True)
        .add_extension(
            x509.KeyUsage(
                False,
                False,
                False,
                False,
                False,
                key_cert_sign=True,
                crl_sign=True,
                encipher_only=False,
                decipher_only=False,
            ),
            critical=True,
        )
        .add_extension(ski, critical=False)
        .sign(key, hashes.SHA256())
    )


def _server(
    key: ec.EllipticCurvePrivateKey,
    ca_key: ec.EllipticCurvePrivateKey,
    ca_cert: x509.Certificate,
    names: Sequence[str],
    now: datetime.datetime,
) -> x509.Certificate:
    alt: list[x509.GeneralName] = []
    for n in names:
        try:
            alt.append(x509.IPAddress(ipaddress.ip_address(n)))
        except ValueError:
            alt.append(x509.DNSName(n))
    ca_ski = ca_cert.extensions.get_extension_for_class(x509.SubjectKeyIdentifier).value
    return (
        x509.CertificateBuilder()
        .subject_name(x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, names[0])]))
        .issuer_name(ca_cert.subject)
        .public_key(key.public_key())
        .serial_number(x509.random_serial_number())
        .not_valid_before(now - datetime.timedelta(minutes=5))
        .not_valid_after(now + datetime.timedelta(days=SERVER_DAYS))
        .add_extension(x509.SubjectAlternativeName(alt), critical=False)
        .add_extension(x509.BasicConstraints(ca=False, path_length=None), critical=True)
        .add_extension(
            x509.KeyUsage(True, False, False, False, False, False, False, encipher_only=False, decipher_only=False),
            critical=True,
        )
        .add_extension(x509.ExtendedKeyUsage([ExtendedKeyUsageOID.SERVER_AUTH]), critical=False)
        .add_extension(x509.AuthorityKeyIdentifier.from_issuer_subject_key_identifier(ca_ski), critical=False)
        .add_extension(x509.SubjectKeyIdentifier.from_public_key(key.public_key()), critical=False)
        .sign(ca_key, hashes.SHA256())
    )


def _write_key(path: Path, key: ec.EllipticCurvePrivateKey) -> None:
    write_secret(
        path,
        key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8, serialization.NoEncryption()),
    )


_LABEL = re.compile(r"^(?!-)[A-Za-z0-9-]{1,63}(?<!-)$")


def _nameable(name: str) -> bool:
    """An IP address, or a DNS name of RFC 1123 labels (what a certificate's names may be)."""
    try:
        ipaddress.ip_address(name)
        return True
    except ValueError:
        return 0 < len(name) <= 253 and all(_LABEL.match(label) for label in name.rstrip(".").split("."))


def names_of(cert: str | os.PathLike[str]) -> list[str]:
    """The host names and addresses a certificate (PEM, its first) is for."""
    first = x509.load_pem_x509_certificates(Path(cert).read_bytes())[0]
    try:
        alt = first.extensions.get_extension_for_class(x509.SubjectAlternativeName).value
    except x509.ExtensionNotFound:
        return []
    return [*alt.get_values_for_type(x509.DNSName), *(str(a) for a in alt.get_values_for_type(x509.IPAddress))]
