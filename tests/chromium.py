"""The headless Chromium the browser tests drive with Playwright (Debian's; CHROMIUM_PATH overrides),
and the mark that skips them, saying why, only where none is installed (.ci/run installs it).
EXGEN_SCREENSHOTS names a folder to write the screenshots the docs show."""
import os
import shutil
from pathlib import Path

import pytest

CHROMIUM = os.environ.get("CHROMIUM_PATH") or shutil.which("chromium") or "/usr/bin/chromium"
SHOTS = os.environ.get("EXGEN_SCREENSHOTS")
needs_chromium = pytest.mark.skipif(not Path(CHROMIUM).exists(),
                                    reason=f"no Chromium at {CHROMIUM} (apt-get install chromium, or set CHROMIUM_PATH)")
