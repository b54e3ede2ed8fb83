/*
 * 02 - your first frame, in C.
 *
 * Example 01 through the C ABI (eoir.h) itself: create an engine, add two
 * GEO satellites and a camera, point it, render one 64 x 64 frame and read
 * the electrons image and the truth. Every call returns an eoir_status;
 * eoir_last_error() names what went wrong (e.g. the property).
 *
 *   cc -std=c99 02_first_frame.c $(pkg-config --cflags --libs eoir) -o first_frame
 *   ./first_frame [OUTPUT_DIR]
 *
 * Makes first_frame_c_electrons.csv (rows of the image, top row first),
 * first_frame_c.pgm (the display image: a portable graymap any viewer opens)
 * and first_frame_c_truth.csv. Exit status 1 if a call fails or the
 * neighbour is not at the image centre.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <eoir/eoir.h>

#define N 64 /* pixels across */

/* Prints the engine's message and stops the program if a call failed. */
static void check(eoir_status status, const char* what) {
  if (status == EOIR_OK) return;
  fprintf(stderr, "02_first_frame: %s: %s (%s)\n", what, eoir_last_error(), eoir_status_name(status));
  exit(1);
}

static FILE* open_output(const char* dir, const char* name, char* path, size_t capacity) {
  snprintf(path, capacity, "%s/%s", dir, name);
  FILE* f = fopen(path, "w");
  if (f == NULL) {
    perror(path);
    exit(1);
  }
  return f;
}

/* A J2000 state at rest: position in metres, identity attitude. */
static eoir_state at_rest(double x_m, double y_m, double z_m) {
  eoir_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s; /* every struct says how much of it the caller knows */
  s.frame = EOIR_FRAME_J2000;
  s.position[0] = x_m;
  s.position[1] = y_m;
  s.position[2] = z_m;
  s.attitude[0] = 1.0; /* {w, x, y, z} */
  return s;
}

int main(int argc, char** argv) {
  const char* dir = argc > 1 ? argv[1] : ".";
  char path[4096];
  printf("engine %s\n", eoir_version_string());

  /* An engine (NULL: every core, seed 1) holds the Sun at J2000.0. */
  eoir_engine engine = NULL;
  check(eoir_engine_create(NULL, &engine), "eoir_engine_create");
  eoir_time t;
  check(eoir_time_from_iso("2010-08-25T18:00:00Z", &t), "time");
  check(eoir_engine_set_time(engine, &t), "eoir_engine_set_time");

  /* Two satellites: a bare platform and a 3 x 2 x 2 m box in gold foil 30 km
   * away on the side away from the Sun (its J2000 position, read with
   * eoir_object_get_state), so that we see its sunlit faces. */
  check(eoir_object_add(engine, EOIR_KIND_SATELLITE, "Observer"), "add Observer");
  check(eoir_set_string(engine, "Observer", "shape", "none"), "Observer shape");
  eoir_state s = at_rest(42164e3, 0.0, 0.0);
  check(eoir_object_set_state(engine, "Observer", NULL, &s), "Observer state");
  check(eoir_object_add(engine, EOIR_KIND_SATELLITE, "Neighbour"), "add Neighbour");
  check(eoir_set_string(engine, "Neighbour", "shape", "box"), "Neighbour shape");
  const double box_m[3] = {3.0, 2.0, 2.0};
  check(eoir_set_array(engine, "Neighbour", "dimensions_m", box_m, 3), "Neighbour dimensions_m");
  check(eoir_set_string(engine, "Neighbour", "material", "gold_mli"), "Neighbour material");
  eoir_state sun;
  memset(&sun, 0, sizeof sun);
  sun.struct_size = sizeof sun;
  sun.frame = EOIR_FRAME_J2000;
  check(eoir_object_get_state(engine, "Sun", &sun), "Sun state");
  const double sun_m = sqrt(sun.position[0] * sun.position[0] + sun.position[1] * sun.position[1] +
                            sun.position[2] * sun.position[2]);
  s = at_rest(42164e3 - 30e3 * sun.position[0] / sun_m, -30e3 * sun.position[1] / sun_m,
              5e3 - 30e3 * sun.position[2] / sun_m);
  check(eoir_object_set_state(engine, "Neighbour", NULL, &s), "Neighbour state");

  /* The camera rides on the observer: 64 x 64 pixels over 0.1 deg, visible. */
  check(eoir_sensor_add(engine, "Camera", "Observer"), "add Camera");
  check(eoir_set_integer(engine, "Camera", "horizontal_pixels", N), "horizontal_pixels");
  check(eoir_set_integer(engine, "Camera", "vertical_pixels", N), "vertical_pixels");
  check(eoir_set_number(engine, "Camera", "horizontal_fov_deg", 0.1), "horizontal_fov_deg");
  check(eoir_set_number(engine, "Camera", "vertical_fov_deg", 0.1), "vertical_fov_deg");
  check(eoir_set_number(engine, "Camera", "band_low_um", 0.45), "band_low_um");
  check(eoir_set_number(engine, "Camera", "band_high_um", 0.9), "band_high_um");
  check(eoir_set_number(engine, "Camera", "integration_time_ms", 100.0), "integration_time_ms");

  /* Boresight (body +z) at the neighbour, then one frame at the engine time. */
  check(eoir_sensor_point_at(engine, "Camera", "Neighbour"), "eoir_sensor_point_at");
  check(eoir_render(engine, "Camera"), "eoir_render");

  /* The images: caller-allocated buffers, row 0 at the top. */
  static double electrons[N * N];
  static uint8_t display[N * N];
  check(eoir_image_get(engine, "Camera", EOIR_IMAGE_SENSOR_ELECTRONS, electrons, N * N), "electrons");
  check(eoir_image_get_bytes(engine, "Camera", EOIR_IMAGE_SENSOR_DISPLAY, display, N * N), "display");

  FILE* f = open_output(dir, "first_frame_c_electrons.csv", path, sizeof path);
  double total = 0.0;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) {
      fprintf(f, "%.6g%c", electrons[r * N + c], c + 1 < N ? ',' : '\n');
      total += electrons[r * N + c];
    }
  fclose(f);
  printf("made %s: %d x %d electrons, total %.4g e-\n", path, N, N, total);

  f = open_output(dir, "first_frame_c.pgm", path, sizeof path);
  fprintf(f, "P5\n%d %d\n255\n", N, N);
  fwrite(display, 1, sizeof display, f);
  fclose(f);
  printf("made %s: the display image\n", path);

  /* The truth: every object in the field, with its sub-pixel place. */
  size_t count = 0;
  check(eoir_truth_count(engine, "Camera", &count), "eoir_truth_count");
  f = open_output(dir, "first_frame_c_truth.csv", path, sizeof path);
  fprintf(f, "object,pixel_x,pixel_y,range_m,snr\n");
  int centred = 0;
  for (size_t i = 0; i < count; ++i) {
    eoir_truth row;
    memset(&row, 0, sizeof row);
    row.struct_size = sizeof row;
    check(eoir_truth_get(engine, "Camera", i, &row), "eoir_truth_get");
    fprintf(f, "%s,%.4f,%.4f,%.3f,%.4g\n", row.object, row.pixel_x, row.pixel_y, row.range_m, row.snr);
    printf("%s: pixel (%.2f, %.2f), range %.1f km, SNR %.1f\n", row.object, row.pixel_x, row.pixel_y,
           row.range_m / 1e3, row.snr);
    centred += strcmp(row.object, "Neighbour") == 0 && fabs(row.pixel_x - (N - 1) / 2.0) < 1.0 &&
               fabs(row.pixel_y - (N - 1) / 2.0) < 1.0 && row.snr > 10.0;
  }
  fclose(f);
  printf("made %s: %zu object(s)\n", path, count);

  eoir_engine_destroy(engine);
  if (!centred || total <= 0.0) {
    fprintf(stderr, "02_first_frame: FAILED: the neighbour is not at the image centre or not seen (SNR <= 10)\n");
    return 1;
  }
  return 0;
}
