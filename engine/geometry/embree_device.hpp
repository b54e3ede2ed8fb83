// The one Embree device of the process (creation is slow) and the check of
// its error state after a call.
#pragma once
#include <embree3/rtcore.h>

namespace eoir::geometry {

// Throws eoir::Error(internal) if the device cannot be made.
RTCDevice embree_device();
// Throws eoir::Error(internal) naming `what` if the device recorded an error.
void check_embree(RTCDevice device, const char* what);

}  // namespace eoir::geometry
