// A frame's display images (spec 4.1.2), made on first request.
#include "frame.hpp"

namespace eoir {

const std::vector<std::uint8_t>& Frame::scene_display() const {
  std::call_once(scene_display_made_, [this] {
    if (scene_in_strips) {
      scene_display_storage.clear();
      return;
    }
    scene_display_storage =
        sensor::scene_display(scene.image, scene_display_options, display_threads, std::move(scene_display_storage));
  });
  return scene_display_storage;
}

const std::vector<std::uint8_t>& Frame::sensor_display() const {
  std::call_once(sensor_display_made_, [this] {
    sensor_display_storage = sensor::compress_for_display(sensor.electrons, sensor_display_options, display_threads,
                                                          std::move(sensor_display_storage));
  });
  return sensor_display_storage;
}

}  // namespace eoir
