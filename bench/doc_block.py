"""The measured blocks of the guides: `make bench` rewrites the text between a guide's markers
<!-- NAME:begin --> and <!-- NAME:end --> from the records just measured, and leaves the prose
around them alone."""
from __future__ import annotations

from pathlib import Path


def replace_block(path: Path, name: str, lines: list[str]) -> bool:
    """Puts `lines` between the markers `name` of the guide `path`, each on a line of its own.
    False, and nothing written, when the guide lacks the markers."""
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    text = path.read_text()
    if begin not in text or end not in text:
        return False
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    path.write_text(head + begin + "\n" + "\n".join(lines) + "\n" + end + tail)
    return True
