"""Fill a PDF's form the way Firefox does, with pdf.js (Firefox's viewer, from npm's pdfjs-dist) in headless
Chromium, save it, and render its pages as pdf.js draws them.

pdf.js is installed by `npm ci --prefix tests/pdfjs --omit=optional` (.ci/run does it; the version is pinned in
tests/pdfjs/package-lock.json), or found at PDFJS_DIST. Each field's value is set through the document's
annotation storage, under the id pdf.js gives its widget, as its form layer does when a student types; then
`saveDocument()` writes the values and pdf.js's own appearance streams, as Firefox's "Save" does.
"""
from __future__ import annotations

import base64
import json
import os
from pathlib import Path

PDFJS = Path(os.environ.get("PDFJS_DIST") or Path(__file__).parent / "pdfjs" / "node_modules" / "pdfjs-dist")
MISSING = f"no pdf.js at {PDFJS} (npm ci --prefix tests/pdfjs --omit=optional, or set PDFJS_DIST)"
ORIGIN = "http://pdfjs.test"  # served by Playwright's routing from the files on disk: no server is started
_TYPES = {".mjs": "text/javascript", ".js": "text/javascript", ".html": "text/html", ".pfb": "application/octet-stream"}

_OPEN = """async function open(data) {
  const pdfjs = await import("/pdfjs-dist/build/pdf.mjs");
  pdfjs.GlobalWorkerOptions.workerSrc = "/pdfjs-dist/build/pdf.worker.mjs";
  const bytes = Uint8Array.from(atob(data), c => c.charCodeAt(0));
  const doc = await pdfjs.getDocument({ data: bytes, isEvalSupported: false, enableScripting: false,
    standardFontDataUrl: "/pdfjs-dist/standard_fonts/" }).promise;
  return [pdfjs, doc];
}
function base64(bytes) {
  let text = "";
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(text);
}
"""

_FILL = """async ({ data, values }) => {
""" + _OPEN + """
  const [pdfjs, doc] = await open(data);
  const found = [];
  const fields = await doc.getFieldObjects();  // a Map in pdf.js 6, a plain object before
  for (const [name, objects] of (fields instanceof Map ? fields : Object.entries(fields || {}))) {
    for (const field of objects) {
      if (!field.id || !field.type) continue;  // a question's parent field: no widget of its own
      found.push([name, field.type, (field.items || []).map(item => item.exportValue)]);
      if (name in values) doc.annotationStorage.setValue(field.id, { value: values[name] });
    }
  }
  return { found, saved: base64(await doc.saveDocument()) };
}"""

_RENDER = """async ({ data, scale }) => {
""" + _OPEN + """
  const [pdfjs, doc] = await open(data);
  const pages = [];
  for (let n = 1; n <= doc.numPages; n++) {
    const page = await doc.getPage(n);
    const viewport = page.getViewport({ scale });
    const canvas = document.createElement("canvas");
    canvas.width = Math.ceil(viewport.width);
    canvas.height = Math.ceil(viewport.height);
    const context = canvas.getContext("2d", { willReadFrequently: true });
    await page.render({ canvas, canvasContext: context, viewport, annotationMode: pdfjs.AnnotationMode.ENABLE }).promise;
    const boxes = [];
    for (const annotation of await page.getAnnotations()) {
      if (annotation.subtype !== "Widget") continue;
      const [a, b, c, d, e, f] = viewport.transform;
      const point = (x, y) => [a * x + c * y + e, b * x + d * y + f];
      const [[x0, y0], [x1, y1]] = [point(annotation.rect[0], annotation.rect[1]), point(annotation.rect[2], annotation.rect[3])];
      const left = Math.round(Math.min(x0, x1)), top = Math.round(Math.min(y0, y1));
      const width = Math.round(Math.abs(x1 - x0)), height = Math.round(Math.abs(y1 - y0)) - 3;  // above the line
      const pixels = context.getImageData(left, top, width, height).data;
      let dark = 0;
      for (let i = 0; i < pixels.length; i += 4) if (pixels[i] + pixels[i + 1] + pixels[i + 2] < 300) dark++;
      boxes.push([annotation.fieldName, dark]);
    }
    pages.push({ png: canvas.toDataURL("image/png").split(",")[1], boxes });
  }
  return pages;
}"""


class PdfJs:
    """pdf.js in one page of a headless Chromium (`browser`, a Playwright browser)."""

    def __init__(self, browser):
        self.page = browser.new_page()
        self.page.route(f"{ORIGIN}/**", self._serve)
        self.page.goto(f"{ORIGIN}/index.html")

    def _serve(self, route):
        path = route.request.url[len(ORIGIN):].split("?")[0]
        if path == "/index.html":
            return route.fulfill(status=200, content_type="text/html", body="<!doctype html><title>pdf.js</title>")
        file = (PDFJS / path.removeprefix("/pdfjs-dist/")).resolve()
        if not path.startswith("/pdfjs-dist/") or PDFJS.resolve() not in file.parents or not file.is_file():
            return route.fulfill(status=404, body="")
        return route.fulfill(status=200, content_type=_TYPES.get(file.suffix, "application/octet-stream"),
                             body=file.read_bytes())

    def fill(self, path: Path, values: dict[str, str], out: Path) -> list[tuple[str, str, list[str]]]:
        """Set `values` (full field name -> text, or a choice's export value) in the PDF at `path` and save it
        to `out`; returns (name, pdf.js's field type, choices) of every field pdf.js found."""
        result = self.page.evaluate(_FILL, {"data": base64.b64encode(path.read_bytes()).decode(), "values": values})
        out.write_bytes(base64.b64decode(result["saved"]))
        return [tuple(f) for f in result["found"]]

    def render(self, pdf: bytes, scale: float = 1.5) -> list[dict]:
        """Every page as pdf.js draws it with its annotations' appearances: {png: bytes, boxes: [(field name,
        dark pixels inside the field above its line)]}."""
        pages = self.page.evaluate(_RENDER, {"data": base64.b64encode(pdf).decode(), "scale": scale})
        return [{"png": base64.b64decode(p["png"]), "boxes": [tuple(b) for b in p["boxes"]]} for p in pages]


def installed() -> bool:
    return (PDFJS / "build" / "pdf.mjs").is_file()


def version() -> str:
    return json.loads((PDFJS / "package.json").read_text())["version"]
