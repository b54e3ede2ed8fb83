# ERFA (the BSD-licensed SOFA): time scales and Earth rotation. pkg-config only.
find_package(PkgConfig REQUIRED)
pkg_check_modules(PC_ERFA QUIET erfa)
find_path(ERFA_INCLUDE_DIR erfa.h HINTS ${PC_ERFA_INCLUDE_DIRS})
find_library(ERFA_LIBRARY erfa HINTS ${PC_ERFA_LIBRARY_DIRS})
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ERFA REQUIRED_VARS ERFA_LIBRARY ERFA_INCLUDE_DIR)
if(ERFA_FOUND AND NOT TARGET ERFA::erfa)
  add_library(ERFA::erfa UNKNOWN IMPORTED)
  set_target_properties(ERFA::erfa PROPERTIES IMPORTED_LOCATION ${ERFA_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${ERFA_INCLUDE_DIR})
endif()
