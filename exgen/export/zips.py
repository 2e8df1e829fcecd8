"""Zip packages written the same way every time: sorted-free (in the order given), fixed dates, deflated."""
from __future__ import annotations

import zipfile
from pathlib import Path

#: Every entry's date: a package depends only on what it holds (zip dates cannot be before 1980).
FIXED_DATE = (2020, 1, 1, 0, 0, 0)


def write_zip(files: dict[str, bytes], path: Path) -> Path:
    """`files` (zip path -> bytes; a path ending in '/' is a folder entry) as a zip at `path`."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for name, data in files.items():
            info = zipfile.ZipInfo(name, FIXED_DATE)
            info.compress_type = zipfile.ZIP_STORED if name.endswith("/") else zipfile.ZIP_DEFLATED
            info.external_attr = (0o40755 if name.endswith("/") else 0o644) << 16
            archive.writestr(info, data)
    return path
