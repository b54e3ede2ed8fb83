#!/usr/bin/env python3
"""Validates JSON files against a JSON Schema (draft 2020-12). References to
the other schemas ("sensor.schema.json#/$defs/parameters") resolve to the
files beside SCHEMA, by their one $id host (https://eoir.invalid/schemas/).

usage: validate_json.py [--invalid] SCHEMA FILE...
  --invalid   every FILE must be refused (each refusal is printed)
"""
import glob
import json
import os
import sys

import jsonschema


def validator_for(schema_file):
    schema = json.load(open(schema_file))
    store = {}
    for path in glob.glob(os.path.join(os.path.dirname(os.path.abspath(schema_file)), "*.schema.json")):
        other = json.load(open(path))
        jsonschema.Draft202012Validator.check_schema(other)
        assert other["$id"] == "https://eoir.invalid/schemas/" + os.path.basename(path), (path, other["$id"])
        store[other["$id"]] = other
    resolver = jsonschema.RefResolver.from_schema(schema, store=store)
    return jsonschema.Draft202012Validator(schema, resolver=resolver)


def main():
    args = sys.argv[1:]
    invalid = args and args[0] == "--invalid"
    if invalid:
        args = args[1:]
    validator = validator_for(args[0])
    failures = 0
    for name in args[1:]:
        with open(name) as f:
            doc = json.load(f)
        errors = sorted(validator.iter_errors(doc), key=lambda e: list(e.path))
        for e in errors:
            print(f"{'refused' if invalid else 'FAIL'} {name}: {'/'.join(map(str, e.path))}: {e.message[:300]}")
        if invalid and not errors:
            print(f"FAIL {name}: accepted, expected a refusal")
        if not errors and not invalid:
            print(f"ok   {name}")
        failures += bool(errors) != bool(invalid)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
