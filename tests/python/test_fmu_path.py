"""udmap.fmu_path: the generic FMUs are found in the package's own data directory
udmap/fmu/ (where a wheel carries them), then UDMAP_BUILD_DIR and the checkout's build/."""
from __future__ import annotations

import pytest

from udmap import InputError, locate


@pytest.mark.parametrize("version", [2, 3])
def test_build_directory_first(version, monkeypatch, fmus):
    monkeypatch.setenv("UDMAP_BUILD_DIR", str(fmus[version].parent))
    assert locate.fmu_path(version) == fmus[version]


@pytest.mark.parametrize("version", [2, 3])
def test_package_data_directory(version, monkeypatch, tmp_path, fmus):
    package = tmp_path / "site-packages" / "udmap"
    (package / "fmu").mkdir(parents=True)
    target = package / "fmu" / locate.FMU_NAMES[version]
    target.write_bytes(fmus[version].read_bytes())
    empty = tmp_path / "empty"
    empty.mkdir()
    monkeypatch.setenv("UDMAP_BUILD_DIR", str(empty))
    monkeypatch.delenv("UDMAP_PREFIX", raising=False)
    monkeypatch.setattr(locate, "PACKAGE_DIR", package)  # as installed: no checkout around it
    assert locate.fmu_path(version) == target


def test_missing_and_bad_version(monkeypatch, tmp_path):
    monkeypatch.setenv("UDMAP_BUILD_DIR", str(tmp_path))
    monkeypatch.delenv("UDMAP_PREFIX", raising=False)
    monkeypatch.setattr(locate, "PACKAGE_DIR", tmp_path / "a" / "b" / "c" / "udmap")
    with pytest.raises(InputError, match="was not found"):
        locate.fmu_path(3)
    with pytest.raises(InputError, match="2 or 3"):
        locate.fmu_path(4)
