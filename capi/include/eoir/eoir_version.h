/*
 * eoir_version.h: the version of the EOIR engine and of its C ABI, included
 * by eoir.h. Written by CMake from capi/eoir_version.h.in with the version
 * of project(eoir VERSION ...) in CMakeLists.txt, the project's one version
 * (do not edit: a configure rewrites it when that version changes).
 */
#ifndef EOIR_EOIR_VERSION_H
#define EOIR_EOIR_VERSION_H

#define EOIR_VERSION_MAJOR 1 /* the soname: libeoir.so.MAJOR */
#define EOIR_VERSION_MINOR 7 /* counts additions to the ABI */
#define EOIR_VERSION_PATCH 0 /* fixes */
#define EOIR_VERSION_STRING "1.7.0"

#endif
