// libFuzzer target: a user star catalogue (engine/universe/star_catalog.cpp,
// StarCatalog::load_csv) on arbitrary bytes. Refusals are Error(corrupt_file)
// with a message; anything else is a finding, and so is a load that holds
// more heap than 16 times the file (issue 25, item 5) plus a constant: 64
// KiB and the sky-cell table every catalogue holds, whatever its size (one
// uint32 offset per cell and one more, 41,252 cells: star_catalog.hpp).
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"
#include "fuzz_common.hpp"
#include "fuzz_heap_bound.hpp"
#include "universe/star_catalog.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const char* path = eoir_fuzz::write_input(data, size);
  try {
    constexpr std::size_t kCellTable_bytes = (41252 + 1) * sizeof(std::uint32_t);
    eoir_fuzz::within_heap_bound(size, 16.0, (std::size_t{64} << 10) + kCellTable_bytes, [&] {
      const auto catalogue = eoir::universe::StarCatalog::load_csv(path, 2016.0);
      const auto selection = catalogue.select_brighter_than(9.0);
      if (selection.indices.size() > catalogue.size()) std::abort();
    });
  } catch (const eoir::Error& e) {
    if (e.status() != eoir::Status::corrupt_file || e.what()[0] == '\0') {
      std::fprintf(stderr, "fuzz: unexpected status %d: '%s'\n", static_cast<int>(e.status()), e.what());
      std::abort();
    }
  }
  return 0;
}
