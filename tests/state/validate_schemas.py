"""Validates files the engine wrote against the JSON Schemas in schemas/."""
import json
import sys

import jsonschema

pairs = [(sys.argv[i], sys.argv[i + 1]) for i in range(1, len(sys.argv), 2)]
for document, schema in pairs:
    with open(document) as f:
        doc = json.load(f)
    with open(schema) as f:
        sch = json.load(f)
    jsonschema.validate(doc, sch)
    print(f"{document}: valid against {schema}")
print(f"{len(pairs)} passed, 0 failed")
