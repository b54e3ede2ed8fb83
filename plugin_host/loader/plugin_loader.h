/*
 * plugin_loader.h — load libeoir.so as a plugin (C99).
 *
 * Hosts never link libeoir directly (as STK loads EOIR): they dlopen() the
 * library at run time, resolve its single entry point eoir_plugin_entry
 * (EOIR_PLUGIN_ENTRY_SYMBOL), ask for the ABI major they were compiled with
 * and call the engine only through the returned function table.
 *
 * Library path, first match wins:
 *   1. the `path` argument of eoir_loader_open (if not NULL and not ""),
 *   2. the environment variable EOIR_LIBRARY,
 *   3. the library beside the program: <directory of the executable>/
 *      EOIR_RELATIVE_LIBRARY (../lib/libeoir.so.1 in an installed tree;
 *      the build tree has the same layout, build/bin and build/lib),
 *   4. the library of the build tree (compile definition EOIR_DEFAULT_LIBRARY).
 */
#ifndef EOIR_PLUGIN_LOADER_H
#define EOIR_PLUGIN_LOADER_H

#include <stddef.h>
#include <stdint.h>

#include "eoir/eoir.h"

#ifdef __cplusplus
extern "C" {
#endif

#define EOIR_LOADER_PATH_MAX 4096
#define EOIR_LOADER_MESSAGE_MAX 1024

typedef struct eoir_loader_plugin {
  void* handle;              /* dlopen handle, NULL when not loaded */
  const eoir_api_v1* api;    /* the engine's function table (ABI major 1) */
  uint32_t abi_major;        /* major that was negotiated */
  char path[EOIR_LOADER_PATH_MAX]; /* library that was opened */
} eoir_loader_plugin;

/* The path eoir_loader_open would use for `path` (argument, EOIR_LIBRARY,
 * build default). Static or environment storage; never NULL. */
const char* eoir_loader_resolve_path(const char* path);

/* Opens the library, resolves eoir_plugin_entry, requests `abi_major`
 * (pass EOIR_VERSION_MAJOR) and checks the table's struct_size and abi_major.
 * `host` may be NULL. On failure returns a negative eoir_status
 * (EOIR_ERR_IO if the library or its entry point cannot be loaded,
 * EOIR_ERR_ABI_MISMATCH, EOIR_ERR_STRUCT_SIZE), writes a message to
 * `message` (capacity bytes, may be NULL) and leaves *plugin unloaded.
 * A mismatched major reads:
 *   "engine library X provides ABI major N; this host needs major M". */
eoir_status eoir_loader_open(const char* path, uint32_t abi_major, const eoir_host_api* host,
                             eoir_loader_plugin* plugin, char* message, size_t capacity);

/* dlclose()s the library. Accepts NULL and an unloaded plugin. Destroy every
 * engine created through the table first. */
void eoir_loader_close(eoir_loader_plugin* plugin);

#ifdef __cplusplus
}
#endif
#endif /* EOIR_PLUGIN_LOADER_H */
