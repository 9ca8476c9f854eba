#!/usr/bin/env python3
"""The layering rules of docs/design.md, checked on every #include (ctest -R layering).

- No include reaches another folder by a relative path ("../").
- A quoted include is either a public header ("shadowkit/<layer>/..."), a test helper
  ("testing/...", tests and benchmarks only), or a private header of the including file's own
  folder or one of its subfolders.
- A layer includes public headers of its own layer and the layers below only:
  core < scene < raster < methods < app < cli.
- A method's own code includes only the methods interface (shadow_method.h, mask_compare.h)
  and its own public header, never another method's or the registry; its tests and
  benchmarks may include any method's public header.
"""
import pathlib
import re
import sys

LAYERS = ["core", "scene", "raster", "methods", "app", "cli"]
METHODS = ["raytrace", "shadowmap", "volume", "svbsp", "angular", "voxel"]
METHOD_INTERFACE = {"shadow_method.h", "mask_compare.h"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def where(path):
    """(layer, method or None) of a file under src/, include/shadowkit/ or fuzz/."""
    parts = path.parts
    if parts[0] == "include":
        layer = parts[2]
        method = path.stem if layer == "methods" and path.stem in METHODS else None
        return layer, method
    if parts[0] == "fuzz":
        return "app", None
    if parts[1] == "testing":
        return "testing", None
    layer = parts[1]
    method = parts[2] if layer == "methods" and len(parts) > 3 else None
    return layer, method


def is_test(path):
    return path.stem.endswith(("_test", "_bench")) or "testing" in path.parts


def problems(root, path):
    text = (root / path).read_text(encoding="utf-8")
    layer, method = where(path)
    for number, target in ((text.count("\n", 0, m.start()) + 1, m.group(1))
                           for m in INCLUDE.finditer(text)):
        where_at = f"{path}:{number}: \"{target}\""
        if target.startswith("../") or "/../" in target:
            yield f"{where_at}: reaches another folder by a relative path"
        elif target.startswith("testing/"):
            if not is_test(path):
                yield f"{where_at}: test helpers are for tests and benchmarks only"
        elif target.startswith("shadowkit/"):
            to_layer = target.split("/")[1]
            if layer != "testing" and LAYERS.index(to_layer) > LAYERS.index(layer):
                yield f"{where_at}: the {layer} layer includes the higher {to_layer} layer"
            elif method and not is_test(path) and to_layer == "methods":
                name = pathlib.PurePosixPath(target).name
                if name not in allowed_for_method(method):
                    yield f"{where_at}: a method uses only the interface and its own header"
        elif not (root / path.parent / target).is_file():
            yield f"{where_at}: not a header of this folder; public headers go in include/"


def allowed_for_method(method):
    return METHOD_INTERFACE | {f"{method}.h"}


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    files = [p.relative_to(root) for folder in ("src", "include", "fuzz")
             for p in sorted((root / folder).rglob("*")) if p.suffix in (".h", ".cpp")]
    found = [message for path in files for message in problems(root, path)]
    for message in found:
        print(message)
    print(f"{len(files)} files, {len(found)} layering problem(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
