/* The plugin loader refuses an ABI major the engine does not provide, with a
 * message naming the library and both majors (C99, through the loader API). */
#include <stdio.h>
#include <string.h>

#include "plugin_loader.h"

static int failures = 0;

#define EXPECT(cond, ...)                                    \
  do {                                                       \
    if (!(cond)) {                                           \
      fprintf(stderr, "%s:%d: FAILED %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                          \
      fprintf(stderr, "\n");                                 \
      ++failures;                                            \
    }                                                        \
  } while (0)

int main(int argc, char** argv) {
  const char* library = argc > 1 ? argv[1] : NULL;
  eoir_loader_plugin plugin;
  char message[EOIR_LOADER_MESSAGE_MAX];
  char expected[EOIR_LOADER_MESSAGE_MAX + 128];
  eoir_status s;

  /* Major 2 from a major-1 library: refused, with a clear message. */
  s = eoir_loader_open(library, 2u, NULL, &plugin, message, sizeof message);
  printf("major 2: %s (%d)\n", message, (int)s);
  EXPECT(s == EOIR_ERR_ABI_MISMATCH, "status %d", (int)s);
  EXPECT(plugin.handle == NULL && plugin.api == NULL, "plugin left loaded");
  snprintf(expected, sizeof expected, "engine library %s provides ABI major 1; this host needs major 2",
           eoir_loader_resolve_path(library));
  EXPECT(strcmp(message, expected) == 0, "message '%s', expected '%s'", message, expected);

  /* Major 1 (this header's): accepted, table checked. */
  s = eoir_loader_open(library, EOIR_VERSION_MAJOR, NULL, &plugin, message, sizeof message);
  EXPECT(s == EOIR_OK, "major 1 refused: %s", message);
  if (s == EOIR_OK) {
    eoir_engine engine = NULL;
    EXPECT(plugin.api->abi_major == 1u, "abi_major %u", (unsigned)plugin.api->abi_major);
    EXPECT(plugin.api->struct_size >= sizeof(eoir_api_v1), "struct_size %u", (unsigned)plugin.api->struct_size);
    EXPECT(plugin.api->version() / 10000u == EOIR_VERSION_MAJOR, "version %u", (unsigned)plugin.api->version());
    EXPECT(plugin.api->engine_create(NULL, &engine) == EOIR_OK, "engine_create: %s", plugin.api->last_error());
    plugin.api->engine_destroy(engine);
    eoir_loader_close(&plugin);
    EXPECT(plugin.handle == NULL, "not closed");
  }
  eoir_loader_close(&plugin); /* twice is harmless */
  eoir_loader_close(NULL);

  /* A missing library: a message naming it. */
  s = eoir_loader_open("/nonexistent/libeoir.so", 1u, NULL, &plugin, message, sizeof message);
  printf("missing: %s (%d)\n", message, (int)s);
  EXPECT(s == EOIR_ERR_IO, "status %d", (int)s);
  EXPECT(strstr(message, "/nonexistent/libeoir.so") != NULL, "message '%s'", message);

  if (failures == 0) printf("test_loader_abi: all passed\n");
  return failures == 0 ? 0 : 1;
}
