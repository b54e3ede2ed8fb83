/* The predefined composite satellites of spec 4.3.3 through the C ABI, C99:
 * the composite property takes the name of a data-folder satellite
 * (leo_earth_observing, leo_communications, geo_communications) and stands
 * for its parts, part materials included; reading the property back gives
 * the parts, so a saved state does not depend on the data folder. An unknown
 * name is EOIR_ERR_UNKNOWN_NAME naming the field and listing the known
 * satellites. The GEO communications satellite, sunlit at 10 km in
 * 0.4-0.7 um, is seen: its parts reflect the Sun. */
#include <stdlib.h>

#include "check.h"

int main(void) {
  static char parts[1 << 16];
  eoir_engine e = NULL;
  size_t count = 0;
  const char* names[3] = {"leo_earth_observing", "leo_communications", "geo_communications"};
  const char* materials[3] = {"solar_panel", "silver_mli", "gold_mli"};
  int i;

  OK(eoir_engine_create(NULL, &e));
  host_camera(e, "2010-03-20T12:00:00Z", 16, 0.4, 0.7);
  OK(eoir_set_number(e, "Cam", "horizontal_fov_deg", 0.25));
  OK(eoir_set_number(e, "Cam", "vertical_fov_deg", 0.25));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_set_string(e, "Sat", "shape", "composite"));

  /* Each name stands for its file's parts, with their materials. */
  for (i = 0; i < 3; ++i) {
    OK(eoir_set_string(e, "Sat", "composite", names[i]));
    OK(eoir_get_string(e, "Sat", "composite", parts, sizeof parts));
    CHECK(parts[0] == '[');
    CHECK(strstr(parts, "\"material\"") != NULL);
    CHECK(strstr(parts, materials[i]) != NULL);
  }

  /* Unknown names: refused, the object keeps the GEO satellite. */
  FAILS(eoir_set_string(e, "Sat", "composite", "geo_comms"), EOIR_ERR_UNKNOWN_NAME, "composite: 'geo_comms'");
  FAILS(eoir_set_string(e, "Sat", "composite", "no_such_satellite"), EOIR_ERR_UNKNOWN_NAME, "geo_communications");
  {
    static char after[1 << 16];
    OK(eoir_get_string(e, "Sat", "composite", after, sizeof after));
    CHECK(strcmp(after, parts) == 0);
  }

  /* Sunlit: at the equinox the Sun is along +x of J2000; the satellite sits
   * 1e6 km from the Earth toward it, the host 10 km away on the Sun's side
   * (direction (0.8, 0, -0.6)), its body +z turned toward the satellite by
   * a rotation about y. */
  OK(put_j2000(e, "Sat", 1.0e9, 0, 0));
  {
    eoir_state s;
    const double half = 0.5 * atan2(-0.8, 0.6);
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    s.frame = EOIR_FRAME_J2000;
    s.position[0] = 1.0e9 + 1.0e4 * 0.8;
    s.position[2] = -1.0e4 * 0.6;
    s.attitude[0] = cos(half);
    s.attitude[2] = sin(half);
    OK(eoir_object_set_state(e, "Host", NULL, &s));
  }
  OK(eoir_render(e, "Cam"));
  {
    /* The pixels whose centre sample sees the satellite: its wings and bus. */
    eoir_pick p;
    int x, y, hits = 0;
    double brightest = 0;
    for (y = 0; y < 16; ++y)
      for (x = 0; x < 16; ++x) {
        memset(&p, 0, sizeof p);
        p.struct_size = sizeof p;
        OK(eoir_pick_get(e, "Cam", 1, (uint32_t)x, (uint32_t)y, &p, NULL, NULL, 0, &count));
        CHECK(isfinite(p.effective_radiance));
        if (p.hit && strcmp(p.object, "Sat") == 0) {
          ++hits;
          if (p.effective_radiance > brightest) brightest = p.effective_radiance;
        }
      }
    CHECK(hits >= 4);
    CHECK(brightest > 1e-3); /* sunlit: ~1e-2 W cm^-2 sr^-1 in 0.4-0.7 um */
    printf("GEO communications satellite at 10 km, sunlit, 0.4-0.7 um: %d pixels, brightest %.3e W cm^-2 sr^-1\n",
           hits, brightest);
  }
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
