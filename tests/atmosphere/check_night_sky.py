#!/usr/bin/python3
"""The dark night sky at a good site (issue 20 item 6), through the Python
bindings: a telescope on La Palma (28.76 N, 17.88 W, 2,370 m) looks at the
zenith at 01:12 UTC on 2010-04-15, local midnight a day after new moon (the
Moon below the horizon), the Sun 40+ deg down, the zenith near the north
galactic pole (galactic latitude ~80 deg, ecliptic latitude ~37 deg). Its
band is V's core, 0.505-0.595 um (a boxcar for Johnson V).

Expected: Benn and Ellison (1998, "Brightness of the night sky over La
Palma", New Astron. Rev. 42, 503; ING Technical Note 115): the dark zenith
sky at high galactic and ecliptic latitude is V = 21.9 mag/arcsec^2 at
solar minimum, brighter by a few tenths of a magnitude at solar maximum.
The star field's zodiacal light is set to the ecliptic pole's 60 S10
(zodiacal_light_scale 60 / 202, Leinert et al. 1998; a little fainter than
at this zenith's 35 deg ecliptic latitude) and its starlight is the
engine's whole-sky mean (brighter than at the galactic pole by some 0.2
mag in the total). Tolerance 0.6 mag about 21.9: the solar cycle (the
airglow's continuum was measured near a maximum), the starlight's mean and
the boxcar for V.

Also (the switch and the parts, not a reference): with the Earth's
`airglow` off the sky is fainter by more than 0.3 mag, and the airglow alone
(no star field: no zodiacal light or starlight) is 0-1.5 mag fainter than
the whole.

usage: check_night_sky.py
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "bindings", "python"))
import eoir  # noqa: E402

LOW, HIGH = 0.505, 0.595
ARCSEC2_SR = (math.pi / 180 / 3600) ** 2
V_ZERO_W_CM2_UM = 3.631e-12  # V = 0 at 0.55 um (Bessell 1998)


def zenith_sky_v(airglow=True, star_field=True):
    e = eoir.Engine()
    e.set_time("2010-04-15T01:12:00Z")
    e.add_object("central_body", "Earth")
    e.set("Earth", "atmosphere", "simple")
    e.set("Earth", "visibility_km", 100.0)
    e.set("Earth", "airglow", airglow)
    e.add_object("central_body", "Moon")
    if star_field:
        e.add_object("star_field", "Stars")
        e.set("Stars", "background_light", True)
        e.set("Stars", "zodiacal_light_scale", 60.0 / 202.0)
    e.add_object("site", "LaPalma")
    e.set("LaPalma", "latitude_deg", 28.76)
    e.set("LaPalma", "longitude_deg", -17.88)
    e.set("LaPalma", "height_m", 2370.0)
    e.add_sensor("Scope", "LaPalma")
    for prop, value in (("horizontal_pixels", 16), ("vertical_pixels", 16), ("horizontal_fov_deg", 0.1),
                        ("vertical_fov_deg", 0.1), ("band_low_um", LOW), ("band_high_um", HIGH),
                        ("spectral_intervals", 90), ("noise_enabled", False)):
        e.set("Scope", prop, value)
    e.point_at("Scope", azimuth_deg=0.0, elevation_deg=90.0)
    e.render("Scope")
    darkest = min(e.pick("Scope", x, y, "pixel")["effective_radiance"] for x, y in ((1, 1), (14, 1), (1, 14), (14, 14)))
    e.close()
    mean_spectral = darkest / (HIGH - LOW)  # W cm^-2 sr^-1 um^-1 over the band (the boxcar's SRF is 1)
    return -2.5 * math.log10(mean_spectral * ARCSEC2_SR / V_ZERO_W_CM2_UM)


def main():
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    total = zenith_sky_v()
    check(abs(total - 21.9) < 0.6, f"zenith night sky V = {total:.2f} mag/arcsec^2 (Benn and Ellison 1998: 21.9 +- 0.6)")
    without_airglow = zenith_sky_v(airglow=False)
    check(without_airglow - total > 0.3, f"without the airglow {without_airglow:.2f}: fainter by {without_airglow - total:.2f} (> 0.3)")
    airglow_only = zenith_sky_v(star_field=False)
    check(0.0 < airglow_only - total < 1.5,
          f"the airglow alone {airglow_only:.2f}: {airglow_only - total:.2f} mag fainter than the whole (0-1.5)")
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
