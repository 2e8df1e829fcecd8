"""The practice pages' web fonts: New Computer Modern, the family every PDF and figure is set in, so a
figure's labels sit where their metrics put them and the text reads as on the printed sheet.

The fonts come from the `typst` package, which carries them inside its library (the same files Typst
embeds in the PDFs), and are cut down to the characters a page can show, as WOFF2. New Computer
Modern is under the GUST Font License (LPPL 1.3c): the subsets carry their own names (family
"NewCM exgen") and a note of what was changed; static/NewCM-README.txt points to the originals.

Regenerate after a Typst upgrade (needs fontTools with Brotli, the `fonts` extra):
    python -m practice.web.webfonts
"""
from __future__ import annotations

import struct
import sys
from importlib import util
from pathlib import Path

OUT = Path(__file__).parent / "static"

#: Text faces: Latin with its accents, Greek, punctuation, scripts, letter-like signs, arrows, operators.
TEXT_RANGES = ("U+0020-007E,U+00A0-017F,U+0237,U+02C6-02DD,U+0300-036F,U+0370-03FF,U+1E00-1EFF,U+2000-206F,"
               "U+2070-209F,U+20AC,U+2100-214F,U+2190-21FF,U+2200-22FF,U+2300-23FF,U+25A0-25FF,U+FB00-FB04")
#: The math face besides: brackets and operators of every size and the mathematical alphabets (MathML's
#: single-letter identifiers are set in its italic letters, U+1D44E on; bold and bold italic for vectors).
MATH_RANGES = TEXT_RANGES + ",U+27C0-27EF,U+2980-29FF,U+2A00-2AFF,U+1D400-1D49B,U+1D6A4-1D755,U+1D7CE-1D7D7"
#: (face in Typst's fonts, file written, style name, CSS weight and style, ranges)
FACES = (
    ("NewCM10-Regular", "newcm-exgen-regular.woff2", "Regular", TEXT_RANGES),
    ("NewCM10-Italic", "newcm-exgen-italic.woff2", "Italic", TEXT_RANGES),
    ("NewCM10-Bold", "newcm-exgen-bold.woff2", "Bold", TEXT_RANGES),
    ("NewCM10-BoldItalic", "newcm-exgen-bolditalic.woff2", "Bold Italic", TEXT_RANGES),
    ("NewCMMath-Regular", "newcm-exgen-math.woff2", "Math", MATH_RANGES),
)


def embedded_fonts(binary: bytes) -> dict[str, bytes]:
    """The OpenType fonts inside a binary, by PostScript name: each found by its header and cut to the
    end of its last table."""
    fonts: dict[str, bytes] = {}
    for magic in (b"OTTO", b"\x00\x01\x00\x00"):
        at = binary.find(magic)
        while at >= 0:
            font = _font_at(binary, at)
            if font:
                fonts.setdefault(_postscript_name(font), font)
            at = binary.find(magic, at + (len(font) if font else 4))
    return fonts


def _font_at(binary: bytes, at: int) -> bytes | None:
    count = struct.unpack(">H", binary[at + 4:at + 6])[0]
    if not 8 <= count <= 40:
        return None
    end, tags = 0, set()
    for i in range(count):
        tag, _, offset, length = struct.unpack(">4sIII", binary[at + 12 + 16 * i:at + 28 + 16 * i])
        if not all(32 <= c < 127 for c in tag):
            return None
        tags.add(tag)
        end = max(end, offset + length)
    if not {b"cmap", b"name", b"head"} <= tags or end > 20_000_000:
        return None
    return binary[at:at + end]


def _postscript_name(font: bytes) -> str:
    count = struct.unpack(">H", font[4:6])[0]
    for i in range(count):
        tag, _, offset, length = struct.unpack(">4sIII", font[12 + 16 * i:28 + 16 * i])
        if tag == b"name":
            table = font[offset:offset + length]
            records, strings = struct.unpack(">H", table[2:4])[0], struct.unpack(">H", table[4:6])[0]
            for j in range(records):
                platform, _, _, name_id, size, start = struct.unpack(">6H", table[6 + 12 * j:18 + 12 * j])
                if name_id == 6:
                    raw = table[strings + start:strings + start + size]
                    return raw.decode("utf-16-be") if platform in (0, 3) else raw.decode("latin-1")
    return ""


def _typst_library() -> Path:
    spec = util.find_spec("typst")
    folder = Path(spec.origin).parent
    return next(p for p in folder.iterdir() if p.name.startswith("_typst") and p.suffix in (".so", ".pyd"))


def subset(font: bytes, style: str, ranges: str) -> bytes:
    """The font cut to `ranges`, with every layout feature and the MATH table, renamed, as WOFF2."""
    import io

    from fontTools import subset as fts
    from fontTools.ttLib import TTFont

    options = fts.Options(layout_features=["*"], name_IDs=["*"], name_languages=["*"], notdef_outline=True,
                          flavor="woff2", glyph_names=False)
    face = TTFont(io.BytesIO(font))
    original = face["name"].getDebugName(4)
    version = face["name"].getDebugName(5)
    subsetter = fts.Subsetter(options)
    subsetter.populate(unicodes=fts.parse_unicodes(ranges))
    subsetter.subset(face)
    names = face["name"]
    family = "NewCM exgen"
    for name_id, text in ((1, family), (16, family), (4, f"{family} {style}"),
                          (6, f"NewCMexgen-{style.replace(' ', '')}"), (3, f"{family} {style} {version}"),
                          (10, f"A subset of {original} ({version}) for exgen's practice pages: the characters "
                               f"{ranges} only, as WOFF2; glyphs, metrics and layout unchanged.")):
        names.removeNames(nameID=name_id)
        names.setName(text, name_id, 3, 1, 0x409)
    out = io.BytesIO()
    face.flavor = "woff2"
    face.save(out)
    return out.getvalue()


def main() -> int:
    fonts = embedded_fonts(_typst_library().read_bytes())
    OUT.mkdir(parents=True, exist_ok=True)
    for source, filename, style, ranges in FACES:
        if source not in fonts:
            print(f"the typst package carries no {source}", file=sys.stderr)
            return 1
        data = subset(fonts[source], style, ranges)
        (OUT / filename).write_bytes(data)
        print(f"{filename}: {len(data) / 1024:.0f} KiB from {source} ({len(fonts[source]) / 1024:.0f} KiB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
