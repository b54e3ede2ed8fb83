"""Sphinx extension of the EOIR manual.

- Runs Doxygen on capi/include/eoir/eoir.h so that Breathe renders the C ABI.
- Expands markers in the pages with tables generated from the code itself,
  so that the reference cannot drift from it:
    <!-- eoir:properties KIND -->   `eoir properties KIND --format json`
    <!-- eoir:providers -->         `eoir groups`
    <!-- eoir:statuses -->          the EOIR_OK / EOIR_ERR_* block of eoir.h
    <!-- eoir:exit-codes -->        the "exit status" line of `eoir --help`
    <!-- eoir:schema FILE -->       schemas/FILE, property by property
    <!-- eoir:validation-scenarios --> scenarios/validation/*.json, name and description
    <!-- eoir:validation-figures -->   scenarios/validation/results/*.png
- Turns every citation of the spec ("spec 4.1.4", "eq. 7", "eqs. 49-55",
  "ERRATA 4.1.5.3", the section column of a table headed "spec") into a link
  to the page that summarises that section (spec.md); a citation of a
  section the page lacks is an undefined label, which fails the build.

The eoir CLI is $EOIR_CLI (CTest sets it), else build/bin/eoir.
"""
import json
import os
import re
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

# Where each numbered equation of the spec stands (from its \tag{N}); eqs. 10
# and 11 are cited by the spec but not printed (ERRATA: eq. 11 is the
# tessellation sum at the end of 4.1.6.1).
EQUATION_SECTION = {1: "4.1.4.1", 2: "4.1.4.2", 3: "4.1.4.2", 10: "4.1.6.1", 11: "4.1.6.1", 12: "4.3.1.3"}
EQUATION_SECTION.update({n: "4.1.5.3" for n in range(4, 10)})
EQUATION_SECTION.update({n: "5.2" for n in range(13, 25)})
EQUATION_SECTION.update({n: "5.4" for n in range(25, 32)})
EQUATION_SECTION.update({32: "5.5", 33: "5.6.1", 34: "5.6.1.1", 35: "5.6.1.2", 36: "5.6.1.3", 37: "5.6.1.3",
                         38: "5.6.2", 39: "5.6.3", 40: "5.7", 41: "5.8", 42: "5.8", 43: "5.9", 44: "5.9",
                         45: "5.10", 46: "5.10", 47: "5.11.1", 48: "5.11.1", 49: "5.11.1", 50: "5.11.2",
                         51: "5.11.2", 52: "5.11.2", 53: "5.11.4", 54: "5.11.4", 55: "5.11.6", 56: "5.12.1",
                         57: "5.12.1"})
EQUATION_SECTION.update({n: "5.13.1" for n in range(58, 63)})
EQUATION_SECTION.update({n: "5.13.2" for n in range(63, 72)})
EQUATION_SECTION.update({n: "5.13.3" for n in range(72, 79)})
TABLE_SECTION = {1: "5.12", 2: "5.13.4", 3: "7.6"}

PROPERTY_KINDS = ["sensor", "satellite", "aircraft", "ground_vehicle", "missile", "site", "star_field",
                  "central_body", "Sun", "Moon", "Mars", "Saturn"]


def eoir_cli():
    cli = os.environ.get("EOIR_CLI") or os.path.join(ROOT, "build", "bin", "eoir")
    if not os.access(cli, os.X_OK):
        raise RuntimeError(f"eoir_docs: no eoir CLI at {cli} (build first, or set EOIR_CLI)")
    return cli


def run_cli(*args):
    return subprocess.run([eoir_cli(), *args], check=True, capture_output=True, text=True).stdout


def cell(text):
    t = str(text).replace("\\", "\\\\").replace("|", "\\|").replace("*", "\\*").replace("<", "&lt;")
    t = t.replace("`", "\\`").replace("\n", " ")
    return t


def code_cell(text):
    t = str(text).replace("|", "\\|")
    return "``" + t + "``" if "`" in t else "`" + t + "`"


def properties_table(kind):
    doc = json.loads(run_cli("properties", kind, "--format", "json"))
    out = ["| property | type | unit | default | range | F | meaning |", "|---|---|---|---|---|---|---|"]
    for p in doc["properties"]:
        d = p["default"]
        d = d if isinstance(d, str) else json.dumps(d)
        if len(d) > 40:
            d = d[:37] + "..."
        rng = p["range"] if p["range"] else "-"
        out.append("| " + " | ".join([code_cell(p["name"]), p["type"], cell(p["unit"] or "-"),
                                      code_cell(d) if d else '`""`', cell(rng), "F" if p["fidelity"] else "",
                                      cell(p["description"])]) + " |")
    return "\n".join(out) + "\n"


def providers_tables():
    out, group = [], None
    for line in run_cli("groups").splitlines():
        if not line.startswith("  "):
            group = line.strip()
            out += ["", f"### {group}", "", "| element | unit | curve against |", "|---|---|---|"]
            continue
        m = re.match(r"^  (.*?)(?: \[(.*?)\])?(?: \(curve vs (.*)\))?$", line)
        out.append(f"| {cell(m.group(1))} | {cell(m.group(2) or '-')} | {cell(m.group(3) or '')} |")
    return "\n".join(out) + "\n"


def statuses_table():
    header = open(os.path.join(ROOT, "capi", "include", "eoir", "eoir.h")).read()
    out = ["| status | value | meaning |", "|---|---|---|"]
    for name, value, comment in re.findall(r"#define (EOIR_(?:OK|ERR_\w+))[ \t]+(-?\d+)[ \t]*(?:/\*(.*?)\*/)?", header):
        out.append(f"| `{name}` | {value} | {cell((comment or '').strip() or 'success')} |")
    return "\n".join(out) + "\n"


def exit_codes_table():
    text = run_cli("--help")
    m = re.search(r"exit status: (.*)", text)
    out = ["| exit status | meaning |", "|---|---|"]
    for code, meaning in re.findall(r"(\d+) ([^,]+)", m.group(1)):
        out.append(f"| {code} | {cell(meaning.strip())} |")
    return "\n".join(out) + "\n"


def schema_type(s):
    if "$ref" in s:
        name = s["$ref"].split("/")[-1]
        return f"{{ref}}`{name} <{slug('schema-def-' + name)}>`" if s["$ref"].startswith("#/$defs/") else cell(s["$ref"])
    if "const" in s:
        return "constant " + code_cell(json.dumps(s["const"]))
    if "enum" in s:
        return "one of " + ", ".join(code_cell(json.dumps(v)) for v in s["enum"])
    for key in ("oneOf", "anyOf"):
        if key in s:
            return " or ".join(schema_type(v) for v in s[key])
    t = s.get("type", "any")
    t = " or ".join(t) if isinstance(t, list) else t
    if t == "array" and isinstance(s.get("items"), dict):
        t += " of " + schema_type(s["items"])
    return t


def schema_limits(s):
    bits = []
    for key, sym in (("minimum", ">="), ("exclusiveMinimum", ">"), ("maximum", "<="), ("exclusiveMaximum", "<"),
                     ("minLength", "length >="), ("maxLength", "length <="), ("minItems", "items >="),
                     ("maxItems", "items <="), ("pattern", "matches")):
        if key in s:
            bits.append(f"{sym} {s[key]}")
    if "default" in s:
        bits.append("default " + json.dumps(s["default"]))
    return cell("; ".join(bits))


def slug(text):
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")


def schema_properties(s, required=()):
    props = s.get("properties", {})
    if not props:
        return []
    out = ["| field | type | constraints | meaning |", "|---|---|---|---|"]
    for name, sub in props.items():
        req = " (required)" if name in required else ""
        out.append(f"| {code_cell(name)}{req} | {schema_type(sub)} | {schema_limits(sub)} | "
                   f"{cell(sub.get('description', ''))} |")
    return out


def schema_page(file_name):
    s = json.load(open(os.path.join(ROOT, "schemas", file_name)))
    out = [cell(s.get("description", "")), ""]
    out += schema_properties(s, s.get("required", ()))
    for name, sub in s.get("$defs", {}).items():
        out += ["", f"({slug('schema-def-' + name)})=", f"### `{name}`", ""]
        if sub.get("description"):
            out += [cell(sub["description"]), ""]
        rows = schema_properties(sub, sub.get("required", ()))
        if rows:
            out += rows
        else:
            out.append(f"Type: {schema_type(sub)}. {schema_limits(sub)}")
        for key in ("oneOf", "anyOf"):
            for i, alt in enumerate(sub.get(key, [])):
                rows = schema_properties(alt, alt.get("required", ()))
                if rows:
                    out += ["", f"Variant {i + 1}{': ' + cell(alt['description']) if alt.get('description') else ''}", ""]
                    out += rows
    return "\n".join(out) + "\n"


def validation_scenarios():
    folder = os.path.join(ROOT, "scenarios", "validation")
    out = ["| scenario | name | what it sets up |", "|---|---|---|"]
    for name in sorted(f for f in os.listdir(folder) if f.endswith(".json")):
        doc = json.load(open(os.path.join(folder, name)))
        out.append(f"| `{name}` | {cell(doc.get('name', ''))} | {cell(doc.get('description', ''))} |")
    return "\n".join(out) + "\n"


def validation_figures(docname):
    folder = os.path.join(ROOT, "scenarios", "validation", "results")
    rel = os.path.relpath(folder, os.path.join(ROOT, "docs", os.path.dirname(docname)))
    out = []
    for name in sorted(f for f in os.listdir(folder) if f.endswith(".png")):
        out += [f"`scenarios/validation/results/{name}`:", "", f"![{name}]({rel}/{name})", ""]
    return "\n".join(out) + "\n"


MARKER = re.compile(r"<!-- eoir:([a-z-]+)(?: ([\w.]+))? -->")


def expand(match, docname=""):
    what, arg = match.group(1), match.group(2)
    if what == "validation-scenarios":
        return validation_scenarios()
    if what == "validation-figures":
        return validation_figures(docname)
    if what == "properties":
        return properties_table(arg)
    if what == "providers":
        return providers_tables()
    if what == "statuses":
        return statuses_table()
    if what == "exit-codes":
        return exit_codes_table()
    if what == "schema":
        return schema_page(arg)
    raise RuntimeError(f"eoir_docs: unknown marker {match.group(0)}")


# ---- spec citations
SECTION = r"\d+(?:\.\d+)*"


def section_label(number):
    return "spec-" + number.replace(".", "-")


def ref(text, number):
    return f"{{ref}}`{text} <{section_label(number)}>`"


def link_prose(text):
    text = re.sub(r"\b([Ss]pec)(\s+)(" + SECTION + r")\b(?!\.\d)", lambda m: ref(f"{m.group(1)} {m.group(3)}", m.group(3)), text)
    text = re.sub(r"\b(ERRATA)(\s+)(" + SECTION + r")\b(?!\.\d)", lambda m: f"{{ref}}`ERRATA {m.group(3)} <errata>`", text)

    def eq(m):
        n = int(m.group(3))
        if n not in EQUATION_SECTION:
            return m.group(0)
        return ref(f"{m.group(1)} {m.group(3)}", EQUATION_SECTION[n])

    text = re.sub(r"\b(eqs?\.|Eqs?\.)(\s+)(\d+)\b", eq, text)

    def table(m):
        return ref(f"Table {m.group(2)}", TABLE_SECTION[int(m.group(2))])

    text = re.sub(r"\b(Table)\s+([123])\b(?!\d|\.\d)", table, text)
    return text


INLINE = re.compile(r"(``.*?``|`[^`]*`|\]\([^)]*\)|<!--.*?-->)", re.S)


def link_citations(source):
    out, fence, chunk = [], None, []
    table_spec_column = False

    def flush():
        if chunk:
            text = "\n".join(chunk)
            parts = INLINE.split(text)
            out.append("".join(p if i % 2 else link_prose(p) for i, p in enumerate(parts)))
            chunk.clear()

    for line in source.split("\n"):
        m = re.match(r"^\s*(`{3,}|~{3,}|:{3,})", line)
        if fence is None and m:
            flush()
            fence = m.group(1)
            out.append(line)
            continue
        if fence is not None:
            out.append(line)
            if line.strip() == fence:
                fence = None
            continue
        if line.startswith("| spec |"):
            table_spec_column = True
        elif not line.startswith("|"):
            table_spec_column = False
        elif table_spec_column and not line.startswith("|---"):
            line = re.sub(r"^\| (" + SECTION + r")\b(?!\.\d)", lambda m: "| " + ref(m.group(1), m.group(1)), line)
        chunk.append(line)
    flush()
    return "\n".join(out)


def source_read(app, docname, source):
    text = MARKER.sub(lambda m: expand(m, docname), source[0])
    if docname != "spec":
        text = link_citations(text)
    source[0] = text


def run_doxygen(app):
    xml = app.config.breathe_projects["eoir"]
    out = os.path.dirname(xml)
    os.makedirs(out, exist_ok=True)
    doxyfile = "\n".join([
        f"INPUT = {os.path.join(ROOT, 'capi', 'include', 'eoir', 'eoir.h')}",
        f"OUTPUT_DIRECTORY = {out}", "GENERATE_XML = YES", "XML_OUTPUT = xml", "GENERATE_HTML = NO",
        "GENERATE_LATEX = NO", "OPTIMIZE_OUTPUT_FOR_C = YES", "EXTRACT_ALL = YES", "QUIET = YES",
        "WARNINGS = NO", "JAVADOC_AUTOBRIEF = YES", "ENABLE_PREPROCESSING = YES", "MACRO_EXPANSION = YES",
        "EXPAND_ONLY_PREDEF = YES", "PREDEFINED = EOIR_API=", "TYPEDEF_HIDES_STRUCT = YES",
        "CASE_SENSE_NAMES = YES", ""])
    subprocess.run(["doxygen", "-"], input=doxyfile, text=True, check=True, cwd=out)


def setup(app):
    app.connect("builder-inited", run_doxygen)
    app.connect("source-read", source_read)
    return {"version": "1", "parallel_read_safe": True}
