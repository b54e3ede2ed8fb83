#!/usr/bin/env python3
"""Regression snapshot of the engine's outputs on the bundled scenarios.

  snapshot.py take BUILD_DIR OUT_DIR [--sensor-parameter KEY=VALUE ...]
                                          # frames (FITS, truth) and every data provider
  snapshot.py compare OLD_DIR NEW_DIR [--rtol 1e-12]

`take` runs the `eoir` CLI of BUILD_DIR on every scenario of scenarios/validation
and scenarios/demo: `eoir run` for the first frames (and again in smooth and bitmap modes
and with exact band integration), and `eoir report` of every provider group for
every sensor (and every target object) at several times. `compare` reports
the largest relative difference of every number (FITS pixels, truth, report
values) and exits 1 if any exceeds --rtol. Used to show that a refactor leaves
results unchanged. `--sensor-parameter` sets a parameter on every sensor of
every scenario (e.g. point_narrow_tables=fft, to compare an option's old path).
"""
import glob, json, os, subprocess, sys
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def read_fits(path):
    """The primary HDU's data of a FITS image written by the CLI (BITPIX -64 or -32)."""
    with open(path, 'rb') as f:
        raw = f.read()
    header, pos = {}, 0
    while True:
        card = raw[pos:pos + 80].decode('ascii'); pos += 80
        key = card[:8].strip()
        if key == 'END':
            break
        if card[8:10] == '= ':
            header[key] = card[10:].split('/')[0].strip()
    pos = (pos + 2879) // 2880 * 2880
    n1, n2, bitpix = int(header['NAXIS1']), int(header['NAXIS2']), int(header['BITPIX'])
    dtype = {-64: '>f8', -32: '>f4', 16: '>i2', 32: '>i4', 8: 'u1'}[bitpix]
    return np.frombuffer(raw, dtype=dtype, count=n1 * n2, offset=pos).reshape(n2, n1).astype(float)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"failed: {' '.join(cmd)}\n{r.stdout}\n{r.stderr}")
    return r.stdout


def iso_plus(iso, seconds):
    from datetime import datetime, timedelta, timezone
    t = datetime.strptime(iso.rstrip('Z'), '%Y-%m-%dT%H:%M:%S').replace(tzinfo=timezone.utc)
    return (t + timedelta(seconds=seconds)).strftime('%Y-%m-%dT%H:%M:%SZ')


def json_or_text(pair):
    """(key, value) with the value parsed as JSON if it is (a number, true), else the text."""
    try:
        return pair[0], json.loads(pair[1])
    except ValueError:
        return pair[0], pair[1]


def take(build, out, sensor_parameters=None):
    eoir = os.path.join(build, 'bin', 'eoir')
    groups = [g.strip() for g in run([eoir, 'groups']).splitlines() if g.strip() and not g.startswith(' ')]
    groups = [g.split('  ')[0] for g in groups if g.startswith('EOIR')]
    scenarios = sorted(glob.glob(os.path.join(ROOT, 'scenarios/validation/*.json'))) + \
        [os.path.join(ROOT, 'scenarios/demo/default.json')]
    for path in scenarios:
        try:
            take_scenario(eoir, groups, path, out, sensor_parameters or {})
        except SystemExit as e:  # one scenario that cannot run does not stop the others
            print(os.path.basename(path), 'FAILED:', str(e).splitlines()[-1] if str(e) else '')


def take_scenario(eoir, groups, path, out, sensor_parameters):
    if True:
        name = os.path.splitext(os.path.basename(path))[0]
        doc = json.load(open(path))
        for s in doc['sensors']:
            s.setdefault('parameters', {}).update(sensor_parameters)
        start, step = doc['start'], float(doc.get('step_s', 60))
        stop_s = 2 * step if doc['stop'] != start else 0
        stop = min(iso_plus(start, stop_s), doc['stop'])  # ISO strings of one form sort as times
        variants = {'base': doc}
        for mode, key, value in (('smooth', 'scene_mode', 'smooth'), ('bitmap', 'scene_mode', 'bitmap'),
                                 ('exact', 'band_integration', 'exact')):
            v = json.loads(json.dumps(doc))
            for s in v['sensors']:
                s.setdefault('parameters', {})[key] = value
            variants[mode] = v
        for vname, vdoc in variants.items():
            d = os.path.join(out, name, vname)
            os.makedirs(d, exist_ok=True)
            spath = os.path.join(d, 'scenario.json')
            json.dump(vdoc, open(spath, 'w'))
            run([eoir, 'run', spath, '--out', os.path.join(d, 'run'), '--start', start, '--stop', stop,
                 '--step', str(step), '--quiet'])
            if vname != 'base':
                continue
            report_stop = doc['stop'] if doc['stop'] != start else start
            span = max(1.0, (json_seconds(report_stop) - json_seconds(start)))
            rstep = str(max(step, span / 24))
            objects = [o['name'] for o in doc.get('objects', [])]
            for s in doc['sensors']:
                for g in groups:
                    targets = objects if 'Target' in g else [None]
                    for t in targets:
                        if t == s.get('parent'):
                            continue
                        cmd = [eoir, 'report', spath, '--provider', g, '--sensor', s['name'], '--start', start,
                               '--stop', report_stop, '--step', rstep, '--format', 'json', '--quiet']
                        if t:
                            cmd += ['--target', t]
                        tag = f"{s['name']}_{g.replace(' ', '_')}" + (f"_{t}" if t else '')
                        try:
                            text = run(cmd)
                        except SystemExit as e:  # e.g. a target of shape none
                            text = json.dumps({'error': str(e).splitlines()[-1] if str(e) else ''})
                        with open(os.path.join(d, f'report_{tag}.json'), 'w') as f:
                            f.write(text)
        print(name, 'ok')


def json_seconds(iso):
    from datetime import datetime, timezone
    return datetime.strptime(iso.rstrip('Z'), '%Y-%m-%dT%H:%M:%S').replace(tzinfo=timezone.utc).timestamp()


def numbers(x, path, out):
    if isinstance(x, bool) or x is None:
        return
    if isinstance(x, (int, float)):
        out[path] = float(x)
    elif isinstance(x, dict):
        for k, v in x.items():
            if k in ('timings', 'elapsed_s', 'engine_library', 'created', 'library', 'seconds', 'wall_s'):
                continue
            numbers(v, f'{path}.{k}', out)
    elif isinstance(x, list):
        for i, v in enumerate(x):
            numbers(v, f'{path}[{i}]', out)


def compare(old, new, rtol):
    worst, bad, count = 0.0, [], 0
    for f in sorted(glob.glob(os.path.join(old, '**', '*'), recursive=True)):
        rel = os.path.relpath(f, old)
        g = os.path.join(new, rel)
        if os.path.isdir(f) or rel.endswith('scenario.json') or rel.endswith('.png'):
            continue
        if not os.path.exists(g):
            bad.append(f'missing {rel}')
            continue
        if f.endswith('.fits'):
            a, b = read_fits(f), read_fits(g)
            if a.shape != b.shape:
                bad.append(f'{rel}: shape {a.shape} != {b.shape}')
                continue
            scale = max(np.max(np.abs(a)), 1e-300)
            d = float(np.max(np.abs(a - b)) / scale) if a.size else 0.0
            count += a.size
        elif f.endswith('.json'):
            na, nb = {}, {}
            numbers(json.load(open(f)), '', na)
            numbers(json.load(open(g)), '', nb)
            d = 0.0
            for k, v in na.items():
                if k not in nb:
                    bad.append(f'{rel}{k}: missing'); continue
                w = nb[k]
                d = max(d, abs(v - w) / max(abs(v), abs(w), 1e-300) if v != w else 0.0)
            count += len(na)
        else:
            continue
        worst = max(worst, d)
        if d > rtol:
            bad.append(f'{rel}: max relative difference {d:.3g}')
    print(f'compared {count} numbers; largest relative difference {worst:.3g}')
    for b in bad:
        print('  ', b)
    return 1 if bad else 0


if __name__ == '__main__':
    if len(sys.argv) >= 4 and sys.argv[1] == 'take':
        pairs = [sys.argv[i + 1] for i, a in enumerate(sys.argv) if a == '--sensor-parameter']
        take(sys.argv[2], sys.argv[3], dict(json_or_text(p.split('=', 1)) for p in pairs))
    elif len(sys.argv) >= 4 and sys.argv[1] == 'compare':
        rtol = float(sys.argv[sys.argv.index('--rtol') + 1]) if '--rtol' in sys.argv else 1e-12
        sys.exit(compare(sys.argv[2], sys.argv[3], rtol))
    else:
        print(__doc__); sys.exit(1)
