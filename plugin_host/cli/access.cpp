#include "access.hpp"

#include <stdexcept>

namespace eoir::cli {

AccessResult find_access(const std::vector<int64_t>& t, const std::function<bool(int64_t)>& inside,
                         const AccessProgress& progress) {
  AccessResult r;
  if (t.empty()) return r;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (t[i] <= t[i - 1]) throw std::invalid_argument("find_access: sample times must increase");
  const auto eval = [&](int64_t ms) {
    ++r.evaluations;
    return inside(ms);
  };
  // 1. Sample the step grid.
  std::vector<char> ok(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    ok[i] = eval(t[i]) ? 1 : 0;
    if (progress) progress("sample", i + 1, t.size());
  }
  std::size_t changes = 0;
  for (std::size_t i = 1; i < t.size(); ++i) changes += ok[i] != ok[i - 1];
  // 2. Refine every change by bisection on the predicate down to adjacent
  //    milliseconds: lo has ok[i-1], hi has ok[i].
  std::size_t refined = 0;
  bool open = ok[0] != 0;
  AccessInterval cur;
  cur.start_ms = t[0];
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (ok[i] == ok[i - 1]) continue;
    int64_t lo = t[i - 1], hi = t[i];
    const bool lo_ok = ok[i - 1] != 0;
    while (hi - lo > 1) {
      const int64_t mid = lo + (hi - lo) / 2;
      if (eval(mid) == lo_ok) lo = mid;
      else hi = mid;
    }
    if (lo_ok) {  // leaving: lo is the last millisecond inside
      cur.stop_ms = lo;
      r.intervals.push_back(cur);
      open = false;
    } else {  // entering: hi is the first millisecond inside
      cur.start_ms = hi;
      open = true;
    }
    if (progress) progress("refine", ++refined, changes);
  }
  if (open) {
    cur.stop_ms = t.back();
    r.intervals.push_back(cur);
  }
  return r;
}

}  // namespace eoir::cli
