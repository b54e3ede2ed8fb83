"""The schemas agree with the engine's property tables (issue 11, item 8):
every property of schemas/sensor.schema.json and
schemas/object_properties.schema.json is a property the engine lists
(eoir_property_info) with the same type, range (bounds and whether each is
excluded) and closed set of names, and every engine property is in the
schema. A bound changed on one side only fails here."""

import json
import math
import os

import pytest

import eoir

SCHEMAS = os.path.join(os.path.dirname(__file__), "..", "..", "..", "schemas")
OBJECT_KINDS = ("satellite", "aircraft", "ground_vehicle", "missile", "site")
# Names the schema lists as the data folder's, checked against the data by
# data/materials/test_materials.py.
OPEN_SETS = {"material"}


def load(name):
    with open(os.path.join(SCHEMAS, name)) as f:
        return json.load(f)


def engine_properties():
    """Sensor properties, and the union of every object kind's."""
    with eoir.Engine(threads=1) as e:
        e.add_object("satellite", "Host")
        e.add_sensor("Sensor", "Host")
        sensor = {p["name"]: p for p in e.properties("Sensor")}
        objects = {}
        for kind in OBJECT_KINDS:
            e.add_object(kind, kind)
            objects.update({p["name"]: p for p in e.properties(kind)})
        e.add_object("central_body", "Earth")
        objects.update({p["name"]: p for p in e.properties("Earth")})
        e.add_object("star_field", "Stars")
        objects.update({p["name"]: p for p in e.properties("Stars")})
    return sensor, objects


SENSOR, OBJECTS = engine_properties()


def lower_bound(schema, integer):
    """(value, excluded) of a schema's lower bound; an integer's exclusive
    bound m is the inclusive m + 1."""
    if "exclusiveMinimum" in schema:
        return schema["exclusiveMinimum"], True
    return schema.get("minimum"), False


def upper_bound(schema):
    if "exclusiveMaximum" in schema:
        return schema["exclusiveMaximum"], True
    return schema.get("maximum"), False


def same_bound(engine_value, engine_open, schema_value, schema_open, integer, lower):
    if engine_value is None:
        return schema_value is None
    if schema_value is None:
        return False
    if integer and engine_open != schema_open:  # (0, n] == [1, n]
        step = 1 if lower else -1
        if engine_open:
            return math.isclose(engine_value + step, schema_value)
        return math.isclose(engine_value, schema_value + step)
    return engine_open == schema_open and math.isclose(engine_value, schema_value, rel_tol=1e-12)


def resolve(schema, defs):
    if "$ref" in schema:
        return defs[schema["$ref"].rsplit("/", 1)[1]]
    if "$dynamicRef" in schema:
        anchor = schema["$dynamicRef"].lstrip("#")
        return next(d for d in defs.values() if d.get("$dynamicAnchor") == anchor)
    return schema


def check(name, prop, schema, defs):
    schema = resolve(schema, defs)
    kind = prop["type"]
    if prop["choices"] and name not in OPEN_SETS:
        assert sorted(schema.get("enum", [])) == sorted(prop["choices"]), name
        return
    expected = {"number": "number", "integer": "integer", "bool": "boolean", "string": "string", "array": "array"}
    if name not in OPEN_SETS:
        assert schema.get("type") == expected[kind], (name, schema.get("type"), kind)
    if kind == "array":
        schema = schema["items"]
    if kind == "integer" and "enum" in schema:  # e.g. the powers of two of psf_grid_size
        assert (min(schema["enum"]), max(schema["enum"])) == (prop["minimum"], prop["maximum"]), name
        return
    if kind in ("number", "integer", "array"):
        integer = kind == "integer"
        lo, lo_open = lower_bound(schema, integer)
        hi, hi_open = upper_bound(schema)
        assert same_bound(prop["minimum"], prop["minimum_open"], lo, lo_open, integer, True), (
            f"{name}: engine minimum {prop['minimum']} (open {prop['minimum_open']}), schema {lo} (exclusive {lo_open})")
        assert same_bound(prop["maximum"], prop["maximum_open"], hi, hi_open, integer, False), (
            f"{name}: engine maximum {prop['maximum']} (open {prop['maximum_open']}), schema {hi} (exclusive {hi_open})")


@pytest.mark.parametrize("name", sorted(SENSOR))
def test_sensor_schema_matches_engine(name):
    schema = load("sensor.schema.json")
    params = schema["$defs"]["parameters"]["properties"]
    assert name in params, f"{name}: in the engine, not in sensor.schema.json"
    check(name, SENSOR[name], params[name], schema["$defs"])


@pytest.mark.parametrize("name", sorted(OBJECTS))
def test_object_schema_matches_engine(name):
    schema = load("object_properties.schema.json")
    assert name in schema["properties"], f"{name}: in the engine, not in object_properties.schema.json"
    check(name, OBJECTS[name], schema["properties"][name], schema.get("$defs", {}))


def test_schemas_list_nothing_the_engine_lacks():
    params = load("sensor.schema.json")["$defs"]["parameters"]["properties"]
    assert set(params) <= set(SENSOR), set(params) - set(SENSOR)
    objects = load("object_properties.schema.json")["properties"]
    assert set(objects) <= set(OBJECTS), set(objects) - set(OBJECTS)
