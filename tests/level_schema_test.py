#!/usr/bin/env python3
"""Checks levels/level.schema.json against the shipped levels, the documented example, the
invalid levels in tests/invalid_levels/ and a few hand-written mistakes.

Usage: level_schema_test.py [path/to/sightline]
Without the sightline binary, the check that the loader also rejects what the schema rejects
is skipped.
"""

import copy
import importlib.metadata
import json
import pathlib
import re
import subprocess
import sys

try:
    import jsonschema
except ImportError:
    print("level_schema_test: python3-jsonschema is missing (run scripts/setup.sh)",
          file=sys.stderr)
    sys.exit(1)

SOURCE_DIR = pathlib.Path(__file__).resolve().parent.parent
SCHEMA_PATH = SOURCE_DIR / "levels" / "level.schema.json"
INVALID_LEVELS_DIR = SOURCE_DIR / "tests" / "invalid_levels"
DOCS_PATH = SOURCE_DIR / "docs" / "LEVELS.md"

# Small but complete: every hand-written mistake below is a variant of it.
MINIMAL_LEVEL = {
    "format": 1,
    "name": "Minimal",
    "camera": {"position": [0, 1.7, 5]},
    "materials": {"paint": {"color": [0.8, 0.8, 0.8]}},
    "meshes": {"cube": {"box": {"size": [1, 1, 1]}}},
    "entities": {"cube": {"mesh": "cube", "material": "paint"}},
    "lights": {"lamp": {"type": "point", "position": [0, 3, 0], "intensity": 5}},
}


REMOVED = object()  # as a value in variant(): delete the key instead


def variant(path, value):
    """A copy of MINIMAL_LEVEL with the value at `path` (a list of keys) replaced or removed."""
    level = copy.deepcopy(MINIMAL_LEVEL)
    target = level
    for key in path[:-1]:
        target = target[key]
    if value is REMOVED:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return level


TWO_KEYFRAMES = [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]
PAINT = ["materials", "paint"]
CUBE_MESH = ["meshes", "cube"]
CUBE_ENTITY = ["entities", "cube"]
LAMP = ["lights", "lamp"]

# (what is wrong, the level) pairs the schema must reject.
HAND_WRITTEN_INVALID = [
    ("unknown top-level key", variant(["colour"], "red")),
    ("unknown material key", variant(PAINT + ["colour"], [1, 1, 1])),
    ("format is a string", variant(["format"], "1")),
    ("format 2", variant(["format"], 2)),
    ("missing camera", variant(["camera"], REMOVED)),
    ("empty name", variant(["name"], "")),
    ("name of 81 characters", variant(["name"], "x" * 81)),
    ("position is a string", variant(["camera", "position"], "0 1 5")),
    ("position of 2 numbers", variant(["camera", "position"], [0, 1])),
    ("position beyond 100000 m", variant(["camera", "position"], [0, 1, 100001])),
    ("fov of 0 (exclusive bound)", variant(["camera", "fov_degrees"], 0)),
    ("pitch of 90.5", variant(["camera", "pitch_degrees"], 90.5)),
    ("colour component above 1", variant(PAINT + ["color"], [1.5, 0, 0])),
    ("colour string without #", variant(PAINT + ["color"], "d8d2c4")),
    ("roughness of 0 (exclusive bound)", variant(PAINT + ["roughness"], 0)),
    ("both mirror and glass", variant(PAINT, {"mirror": {}, "glass": {"tint": [1, 1, 1]}})),
    ("glass without tint", variant(PAINT, {"glass": {}})),
    ("no materials", variant(["materials"], {})),
    ("invalid material id", variant(["materials", "my paint"], {})),
    ("mesh with two shapes", variant(CUBE_MESH + ["sphere"], {"radius": 1})),
    ("mesh with no shape", variant(CUBE_MESH, {})),
    ("box size of 0", variant(CUBE_MESH + ["box", "size"], [1, 0, 1])),
    ("sphere segments not an integer",
     variant(CUBE_MESH, {"sphere": {"radius": 1, "segments": 3.5}})),
    ("sphere segments above 4096", variant(CUBE_MESH, {"sphere": {"radius": 1, "segments": 4097}})),
    ("glTF node and mesh both", variant(CUBE_MESH, {"gltf": "a.glb", "node": "n", "mesh": "m"})),
    ("node without glTF", variant(CUBE_MESH + ["node"], "n")),
    ("glTF path with another extension", variant(CUBE_MESH, {"gltf": "a.obj"})),
    ("absolute glTF path", variant(CUBE_MESH, {"gltf": "/models/a.glb"})),
    ("percent-encoded glTF path", variant(CUBE_MESH, {"gltf": "%2e%2e/a.glb"})),
    ("entity without mesh", variant(CUBE_ENTITY + ["mesh"], REMOVED)),
    ("scale of 0", variant(CUBE_ENTITY + ["scale"], 0)),
    ("casts_shadow is a string", variant(CUBE_ENTITY + ["casts_shadow"], "no")),
    ("both mover and interactable", variant(CUBE_ENTITY, {
        "mesh": "cube", "material": "paint", "mover": {"keyframes": TWO_KEYFRAMES},
        "interactable": {"type": "switch", "light": "lamp"}})),
    ("mover with one keyframe", variant(CUBE_ENTITY + ["mover"], {"keyframes": TWO_KEYFRAMES[:1]})),
    ("mover duration of 0", variant(CUBE_ENTITY + ["mover"], {
        "duration_seconds": 0, "keyframes": TWO_KEYFRAMES})),
    ("unknown repeat", variant(CUBE_ENTITY + ["mover"], {
        "repeat": "bounce", "keyframes": TWO_KEYFRAMES})),
    ("slide with a rotate key", variant(CUBE_ENTITY + ["interactable"], {
        "type": "slide", "axis": [1, 0, 0], "min": -1, "max": 1, "min_degrees": -1})),
    ("zero axis", variant(CUBE_ENTITY + ["interactable"], {
        "type": "rotate", "axis": [0, 0, 0], "min_degrees": -45, "max_degrees": 45})),
    ("rotate without max_degrees", variant(CUBE_ENTITY + ["interactable"], {
        "type": "rotate", "min_degrees": -45})),
    ("light without intensity", variant(LAMP + ["intensity"], REMOVED)),
    ("negative intensity", variant(LAMP + ["intensity"], -1)),
    ("intensity above 1e9", variant(LAMP + ["intensity"], 2e9)),
    ("unknown light type", variant(LAMP + ["type"], "spot")),
    ("point light with a radius", variant(LAMP + ["radius"], 1)),
    ("sun angular diameter above 30", variant(LAMP, {
        "type": "directional", "direction": [0, -1, 0], "intensity": 1,
        "angular_diameter_degrees": 31})),
    ("rectangle light without size", variant(LAMP, {
        "type": "rectangle", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 1})),
    ("65 lights", variant(["lights"], {
        f"lamp{i}": {"type": "point", "position": [0, 3, 0], "intensity": 1} for i in range(65)})),
    ("max_mirror_bounces of 32", variant(["rendering"], {"max_mirror_bounces": 32})),
    ("goal of unknown type", variant(["goal"], {"type": "win"})),
    ("focus coverage of 0", variant(["goal"], {"type": "focus", "orb": "cube", "coverage": 0})),
    ("nested goal with a bad key", variant(["goal"], {"type": "all", "of": [{"type": "any", "of": [
        {"type": "reach", "min": [0, 0, 0], "max": [1, 1, 1], "radius": 1}]}]})),
    ("all with no goals", variant(["goal"], {"type": "all", "of": []})),
    ("lose is an object", variant(["lose"], {"type": "fall", "below": -5})),
    ("stealth without watcher", variant(["lose"], [{"type": "stealth", "seconds": 1}])),
]


class Results:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, ok, what, detail=""):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print(f"FAIL: {what}" + (f"\n      {detail}" if detail else ""))


def first_error(validator, document):
    error = jsonschema.exceptions.best_match(validator.iter_errors(document))
    return None if error is None else f"{error.json_path}: {error.message}"


def strip_jsonc_comments(text):
    """Drops // comments outside strings, so the documented example can be parsed as JSON."""
    kept = []
    in_string = False
    index = 0
    while index < len(text):
        char = text[index]
        if in_string:
            kept.append(char)
            if char == "\\":
                kept.append(text[index + 1])
                index += 1
            elif char == '"':
                in_string = False
        elif char == '"':
            in_string = True
            kept.append(char)
        elif text.startswith("//", index):
            index = text.find("\n", index)
            if index < 0:
                break
            continue
        else:
            kept.append(char)
        index += 1
    return "".join(kept)


def check_schema_is_valid(results):
    schema = json.loads(SCHEMA_PATH.read_text())
    try:
        jsonschema.Draft202012Validator.check_schema(schema)
        results.check(True, "schema is valid draft 2020-12")
    except jsonschema.exceptions.SchemaError as error:
        results.check(False, "schema is valid draft 2020-12", error.message)
        return None
    return jsonschema.Draft202012Validator(schema)


def check_shipped_levels(validator, results):
    levels = sorted(p for p in (SOURCE_DIR / "levels").glob("*.json") if p != SCHEMA_PATH)
    results.check(bool(levels), "levels/ holds at least one level")
    for level in levels:
        error = first_error(validator, json.loads(level.read_text()))
        results.check(error is None, f"{level.name} matches the schema", error or "")


def check_documented_example(validator, results):
    match = re.search(r"```jsonc\n(.*?)```", DOCS_PATH.read_text(), re.DOTALL)
    if not match:
        results.check(False, "docs/LEVELS.md has a ```jsonc example")
        return
    example = json.loads(strip_jsonc_comments(match.group(1)))
    error = first_error(validator, example)
    results.check(error is None, "the example in docs/LEVELS.md matches the schema", error or "")


def check_hand_written_invalid(validator, results):
    results.check(validator.is_valid(MINIMAL_LEVEL), "the minimal level matches the schema",
                  first_error(validator, MINIMAL_LEVEL) or "")
    for what, level in HAND_WRITTEN_INVALID:
        results.check(not validator.is_valid(level), f"schema rejects: {what}")


def check_invalid_levels(validator, results, sightline):
    # Another suite fills this directory; every file there is meant to be rejected by the loader.
    files = sorted(INVALID_LEVELS_DIR.glob("*.json"))
    if not files:
        print(f"note: no files in {INVALID_LEVELS_DIR}")
        return
    if sightline is None:
        print("note: no sightline binary given; skipping the loader half of the invalid levels")
    rejected_by_schema = 0
    for path in files:
        try:
            document = json.loads(path.read_text())
        except (json.JSONDecodeError, UnicodeDecodeError):
            document = None  # not JSON at all: the schema has nothing to say
        if document is None or validator.is_valid(document):
            continue
        rejected_by_schema += 1
        if sightline is None:
            continue
        run = subprocess.run([sightline, "validate", str(path)], capture_output=True, text=True,
                             timeout=60)
        results.check(run.returncode != 0,
                      f"schema rejects {path.name}, so `sightline validate` must too",
                      f"schema: {first_error(validator, document)}")
    print(f"note: the schema rejects {rejected_by_schema} of {len(files)} invalid levels"
          " (the rest need the loader: references, ordering, files, syntax)")


def main():
    sightline = sys.argv[1] if len(sys.argv) > 1 else None
    if sightline is not None and not pathlib.Path(sightline).is_file():
        print(f"level_schema_test: {sightline} does not exist", file=sys.stderr)
        return 1
    print(f"note: jsonschema {importlib.metadata.version('jsonschema')} on {sys.executable}")
    results = Results()
    validator = check_schema_is_valid(results)
    if validator is not None:
        check_shipped_levels(validator, results)
        check_documented_example(validator, results)
        check_hand_written_invalid(validator, results)
        check_invalid_levels(validator, results, sightline)
    print(f"{results.passed} passed, {results.failed} failed")
    return 0 if results.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
