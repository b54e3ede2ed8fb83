"""Scenario files in Python, through the eoir CLI's own code.

    import eoir
    with eoir.Scenario.load("scenarios/demo/default.json", seed=1) as sc:
        for t in sc.times():                  # the times of `eoir run`
            sc.set_time(t)                    # engine time + every object's state
            sc.engine.render("WideLWIR")
            sc.write_fits("WideLWIR", "sensor_electrons", f"frame_{t}.fits")
            print(sc.truth("WideLWIR"))       # FITS pixels and RA/Dec, as _truth.json

The scenario is loaded, and objects are moved and pointed, by libeoir_host
(plugin_host/hostlib): the same code as `eoir validate/run/report`, not a
second copy in Python. `sc.engine` is an eoir.Engine over the session's
engine (every Engine call works on it; the scenario closes it).
"""

from __future__ import annotations

import ctypes
import json
import os
from ctypes import byref, c_double, c_void_p
from typing import Any, Dict, List, Optional, Union

import numpy as np

from . import _host, _lib
from ._lib import encode, encode_path
from .engine import IMAGE_KINDS, Engine, Time, _Closing, _lookup, _to_c_time

Path = Union[str, "os.PathLike[str]"]


def _iso(time: Time) -> str:
    """An ISO-8601 UTC string for any time the Engine accepts."""
    if isinstance(time, str):
        return time
    t = _to_c_time(time)
    buf = ctypes.create_string_buffer(64)
    _lib.check(_lib.lib.eoir_time_to_iso(byref(t), buf, 64))
    return buf.value.decode()


class Scenario(_Closing):
    """A scenario file loaded into an engine (see the module's docstring)."""

    def __init__(self) -> None:
        raise TypeError("use eoir.Scenario.load(path)")

    @classmethod
    def load(cls, path: Path, seed: int = 1, threads: int = 0, allow_paths_outside: bool = False) -> "Scenario":
        """Reads and checks the scenario file (as `eoir validate` does),
        creates an engine with `seed` and `threads`, registers every body,
        object, sensor and property, and sets the scenario's start time.
        Files the scenario names (a star catalogue) must lie in its folder
        unless allow_paths_outside (`eoir --allow-paths-outside`; README
        "Bounds"). Raises the eoir error of the problem (CorruptFileError
        naming the file and JSON path for a bad scenario)."""
        h = _host.host()
        threads = _lib.threads_argument(threads)
        options = _host.ALLOW_PATHS_OUTSIDE if allow_paths_outside else 0
        session = c_void_p()
        _host.check(h.eoir_host_session_open_with(encode(_lib.library_path, "library_path"), encode_path(path),
                                                  int(seed) & 0xFFFFFFFFFFFFFFFF, threads, options,
                                                  byref(session)))
        self = cls.__new__(cls)
        self._session = session
        self._close = h.eoir_host_session_close
        self.path = os.fspath(path)
        self.seed, self.threads = int(seed), int(threads)
        info = json.loads(_host.json_out(h.eoir_host_session_describe, session))
        self.name: str = info["name"]
        self.description: str = info["description"]
        self.start: str = info["start"]
        self.stop: str = info["stop"]
        self.step_s: float = info["step_s"]
        self.central_bodies: List[str] = info["central_bodies"]
        self.objects: List[Dict[str, str]] = info["objects"]
        self.sensors: List[Dict[str, str]] = info["sensors"]
        self.engine = Engine._adopt(h.eoir_host_session_engine(session), self)
        return self

    # ---------------------------------------------------------- lifetime
    def close(self) -> None:
        session, self._session = getattr(self, "_session", None), None
        if session is not None:
            self.engine.close()
            self._close(session)

    @property
    def session(self) -> c_void_p:
        if self._session is None:
            raise ValueError("the scenario is closed")
        return self._session

    def __repr__(self) -> str:
        return f"<eoir.Scenario {self.name!r}: {len(self.objects)} objects, {len(self.sensors)} sensors>"

    # -------------------------------------------------------------- time
    def times(self, start: Optional[Time] = None, stop: Optional[Time] = None, step_s: Optional[float] = None) -> List[str]:
        """The times of `eoir run`: start (default: the scenario's) to stop
        (default: the scenario's), every step_s (default: the scenario's),
        stop included, as ISO-8601 UTC strings."""
        h = _host.host()
        a = encode(_iso(start), "start") if start is not None else None
        b = encode(_iso(stop), "stop") if stop is not None else None
        return json.loads(_host.json_out(h.eoir_host_session_times, self.session, a, b,
                                         float(step_s) if step_s is not None else 0.0))

    def set_time(self, time: Time) -> None:
        """Sets the engine time and pushes every object's state and attitude
        (the scenario's motion and pointing models); then sensors under
        ``engine.track`` are pointed at their targets."""
        _host.check(_host.host().eoir_host_session_set_time(self.session, encode(_iso(time), "time")))
        self.engine._retrack(strict=False)

    # ------------------------------------------------- truth and FITS files
    def truth(self, sensor: str) -> List[Dict[str, Any]]:
        """The per-frame truth `eoir run` writes for the last frame of
        sensor (schemas/truth.schema.json): FITS pixels (x_fits, y_fits),
        astrometric ICRS ra_deg/dec_deg (what the FITS WCS gives at the
        pixel, as a plate solution does) at the middle of the integration
        (time) and at its start and end (start_time, start_ra_deg, ...),
        apparent_ra_deg/dec_deg and geometric_ra_deg/dec_deg, range, SNR.
        The same fields as Engine.truth() (which adds start and end in
        0-based pixels and None for the fields the file leaves out); the rows
        equal the `_truth.json` file of `eoir run`."""
        return json.loads(_host.json_out(_host.host().eoir_host_session_truth, self.session,
                                         encode(sensor, "sensor")))

    def fits_header(self, sensor: str, kind: Union[str, int] = "sensor_electrons", frame: int = 0) -> Any:
        """The astropy.io.fits.Header `eoir run` writes for the last frame of
        sensor: the integration's DATE-OBS (its start) = DATE-BEG, DATE-AVG,
        DATE-END and MJD cards (UTC), EXPTIME, the observer (OBSGEO-X/Y/Z in
        ITRS; OBSJ2K* J2000 state unless on a site), BUNIT, GAIN, SATURATE
        and RDNOISE where they apply, the sensor and its astrometric TAN WCS
        (ICRS, CD matrix)."""
        from astropy.io import fits
        code = _lookup(IMAGE_KINDS, kind, "image kind")
        cards = json.loads(_host.json_out(_host.host().eoir_host_session_fits_header, self.session,
                                          encode(sensor, "sensor"), code, int(frame)))
        header = fits.Header()
        for key, value, comment in cards:
            if key in ("COMMENT", "HISTORY"):
                header.add_comment(value) if key == "COMMENT" else header.add_history(value)
            elif len(key) > 8 or " " in key:  # e.g. the fidelity knobs, HIERARCH FID <NAME>
                header.append(fits.Card("HIERARCH " + key, value, comment))
            else:
                header.append(fits.Card(key, value, comment))
        return header

    def fits_hdu(self, sensor: str, kind: Union[str, int] = "sensor_electrons", frame: int = 0) -> Any:
        """The last frame of sensor as an astropy PrimaryHDU: float32 pixels in
        FITS order (row 1 at the bottom, as ds9 shows the PNG) with the
        header of fits_header()."""
        from astropy.io import fits
        image = self.engine.image(sensor, kind)
        return fits.PrimaryHDU(np.flipud(image).astype(np.float32), header=self.fits_header(sensor, kind, frame))

    def write_fits(self, sensor: str, kind: Union[str, int], path: Path, frame: int = 0, overwrite: bool = True) -> None:
        """Writes fits_hdu() to path with astropy (checksums included),
        through a temporary file renamed into place."""
        hdu = self.fits_hdu(sensor, kind, frame)
        path = os.fspath(path)
        tmp = f"{path}.tmp.{os.getpid()}"
        try:
            hdu.writeto(tmp, overwrite=True, checksum=True)
            if not overwrite and os.path.exists(path):
                raise FileExistsError(path)
            os.replace(tmp, path)
        finally:
            if os.path.exists(tmp):
                os.unlink(tmp)


def tle_state(line1: str, line2: str, time: Time) -> Dict[str, np.ndarray]:
    """SGP4 from two-line elements at a UTC time, by the host's propagator
    (plugin_host/cli/sgp4.cpp, the "tle" motion of scenarios): TEME position
    (km) and velocity (km/s) as SGP4 gives them, and J2000 position (m) and
    velocity (m/s) as scenarios push them. Raises OutOfRangeError for a bad
    TLE (naming the line and field) or an SGP4 error (decayed...)."""
    arrays = [(c_double * 3)() for _ in range(4)]
    _host.check(_host.host().eoir_host_tle_state(encode(line1, "line1"), encode(line2, "line2"),
                                                 encode(_iso(time), "time"),
                                                 *[byref(a) for a in arrays]))
    names = ("teme_position_km", "teme_velocity_km_s", "position_m", "velocity_m_s")
    return {n: np.array(list(a)) for n, a in zip(names, arrays)}
