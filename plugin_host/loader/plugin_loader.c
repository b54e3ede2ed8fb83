/* plugin_loader.c — see plugin_loader.h. */
#define _XOPEN_SOURCE 700 /* realpath, readlink */
#include "plugin_loader.h"

#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <limits.h>
#include <unistd.h>

#ifndef EOIR_DEFAULT_LIBRARY
#define EOIR_DEFAULT_LIBRARY "libeoir.so.1"
#endif

/* Size of the ABI 1.0 table: every entry this loader's hosts may call. */
#define EOIR_LOADER_MIN_TABLE_SIZE \
  (offsetof(eoir_api_v1, sensor_load) + sizeof(((eoir_api_v1*)0)->sensor_load))

/* Highest major probed to name the one a library provides on a mismatch. */
#define EOIR_LOADER_PROBE_MAX 64u

static void set_message(char* message, size_t capacity, const char* format, ...) {
  va_list args;
  if (message == NULL || capacity == 0) return;
  va_start(args, format);
  vsnprintf(message, capacity, format, args);
  va_end(args);
}

/* The library beside the running program, EOIR_RELATIVE_LIBRARY from its
 * directory (bin/../lib/libeoir.so.1 in an installed tree and in the build
 * tree), or NULL if there is none. */
static const char* library_beside_program(void) {
#ifdef EOIR_RELATIVE_LIBRARY
  static char buffer[PATH_MAX + EOIR_LOADER_PATH_MAX];
  const char* rel = EOIR_RELATIVE_LIBRARY;
  const char* name = strrchr(rel, '/');
  char exe[EOIR_LOADER_PATH_MAX];
  char* slash;
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0 || name == NULL) return NULL;
  exe[n] = '\0';
  slash = strrchr(exe, '/');
  if (slash == NULL) return NULL;
  /* <program dir>/<relative dir>, with ".." resolved (messages show a plain
   * path), then the library's file name (the soname link, not resolved). */
  if ((size_t)(slash - exe) + 1 + (size_t)(name - rel) >= sizeof exe) return NULL;
  memcpy(slash + 1, rel, (size_t)(name - rel));
  slash[1 + (name - rel)] = '\0';
  if (realpath(exe, buffer) == NULL) return NULL;
  if (strlen(buffer) + strlen(name) >= sizeof buffer) return NULL;
  strcat(buffer, name);
  return access(buffer, R_OK) == 0 ? buffer : NULL;
#else
  return NULL;
#endif
}

const char* eoir_loader_resolve_path(const char* path) {
  const char* env;
  const char* beside;
  if (path != NULL && path[0] != '\0') return path;
  env = getenv("EOIR_LIBRARY");
  if (env != NULL && env[0] != '\0') return env;
  beside = library_beside_program();
  if (beside != NULL) return beside;
  return EOIR_DEFAULT_LIBRARY;
}

/* dlsym returns void*; converting it to a function pointer is what POSIX
 * requires to work, done through memcpy to stay clean under -Wpedantic. */
static eoir_plugin_entry_fn resolve_entry(void* handle) {
  eoir_plugin_entry_fn entry = NULL;
  void* symbol = dlsym(handle, EOIR_PLUGIN_ENTRY_SYMBOL);
  if (symbol != NULL) memcpy(&entry, &symbol, sizeof entry);
  return entry;
}

eoir_status eoir_loader_open(const char* path, uint32_t abi_major, const eoir_host_api* host,
                             eoir_loader_plugin* plugin, char* message, size_t capacity) {
  const char* resolved = eoir_loader_resolve_path(path);
  void* handle;
  eoir_plugin_entry_fn entry;
  const void* table = NULL;
  const eoir_api_v1* api;
  eoir_status status;

  set_message(message, capacity, "%s", "");
  if (plugin == NULL) {
    set_message(message, capacity, "eoir_loader_open: plugin is NULL");
    return EOIR_ERR_NULL_ARGUMENT;
  }
  memset(plugin, 0, sizeof *plugin);

  handle = dlopen(resolved, RTLD_NOW | RTLD_LOCAL);
  if (handle == NULL) {
    const char* why = dlerror();
    set_message(message, capacity, "cannot load engine library %s: %s (set EOIR_LIBRARY)", resolved,
                why != NULL ? why : "unknown error");
    return EOIR_ERR_IO;
  }
  entry = resolve_entry(handle);
  if (entry == NULL) {
    set_message(message, capacity, "engine library %s has no entry point %s", resolved,
                EOIR_PLUGIN_ENTRY_SYMBOL);
    dlclose(handle);
    return EOIR_ERR_IO;
  }

  status = entry(abi_major, host, &table);
  if (status == EOIR_ERR_ABI_MISMATCH || (status == EOIR_OK && table == NULL)) {
    /* Name the major the library does provide: probe from 1 upwards. */
    uint32_t provided = 0, m;
    for (m = 1; m <= EOIR_LOADER_PROBE_MAX && provided == 0; ++m) {
      const void* probe = NULL;
      if (m != abi_major && entry(m, host, &probe) == EOIR_OK && probe != NULL) provided = m;
    }
    if (provided != 0)
      set_message(message, capacity, "engine library %s provides ABI major %u; this host needs major %u",
                  resolved, (unsigned)provided, (unsigned)abi_major);
    else
      set_message(message, capacity,
                  "engine library %s does not provide ABI major %u, which this host needs", resolved,
                  (unsigned)abi_major);
    dlclose(handle);
    return EOIR_ERR_ABI_MISMATCH;
  }
  if (status != EOIR_OK) {
    set_message(message, capacity, "engine library %s: %s failed with status %d", resolved,
                EOIR_PLUGIN_ENTRY_SYMBOL, (int)status);
    dlclose(handle);
    return status;
  }

  api = (const eoir_api_v1*)table;
  if (api->abi_major != abi_major) {
    set_message(message, capacity, "engine library %s provides ABI major %u; this host needs major %u",
                resolved, (unsigned)api->abi_major, (unsigned)abi_major);
    dlclose(handle);
    return EOIR_ERR_ABI_MISMATCH;
  }
  if (abi_major == 1 && api->struct_size < EOIR_LOADER_MIN_TABLE_SIZE) {
    set_message(message, capacity,
                "engine library %s: function table of %u bytes is smaller than ABI %u.0 needs (%u bytes)",
                resolved, (unsigned)api->struct_size, (unsigned)abi_major,
                (unsigned)EOIR_LOADER_MIN_TABLE_SIZE);
    dlclose(handle);
    return EOIR_ERR_STRUCT_SIZE;
  }

  plugin->handle = handle;
  plugin->api = api;
  plugin->abi_major = abi_major;
  strncpy(plugin->path, resolved, sizeof plugin->path - 1);
  plugin->path[sizeof plugin->path - 1] = '\0';
  return EOIR_OK;
}

void eoir_loader_close(eoir_loader_plugin* plugin) {
  if (plugin == NULL || plugin->handle == NULL) return;
  dlclose(plugin->handle);
  plugin->handle = NULL;
  plugin->api = NULL;
}
