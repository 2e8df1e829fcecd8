"""The practice pages' fonts come from the fonts Typst embeds in the PDFs: the regenerating tool finds
every face it cuts down inside the installed typst package, and the stylesheet names only files shipped."""
import re
from pathlib import Path

from practice.web import webfonts

STATIC = Path(webfonts.__file__).parent / "static"


def test_the_typst_package_carries_every_face_the_pages_use():
    fonts = webfonts.embedded_fonts(webfonts._typst_library().read_bytes())
    for source, _, _, _ in webfonts.FACES:
        assert source in fonts and fonts[source][:4] == b"OTTO", source


def test_every_face_is_shipped_and_declared():
    css = (STATIC / "practice.css").read_text()
    declared = set(re.findall(r'url\("/static/([^"]+\.woff2)"\)', css))
    assert declared == {filename for _, filename, _, _ in webfonts.FACES}
    for name in declared:
        assert (STATIC / name).read_bytes()[:4] == b"wOF2"
    assert (STATIC / "GUST-FONT-LICENSE.txt").exists() and (STATIC / "LPPL-1.3c.txt").exists()
