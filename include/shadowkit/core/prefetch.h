#pragma once
// Loading an object ahead of its use, where a pass meets objects scattered in memory and
// knows which comes next.
#include <cstddef>

namespace shadowkit {

/// Starts loading every cache line of \p object.
template <class T>
void prefetch(const T& object) {
  constexpr std::size_t kLine = 64;
  const char* first = reinterpret_cast<const char*>(&object);
  for (std::size_t at = 0; at < sizeof(T); at += kLine) __builtin_prefetch(first + at);
}

}  // namespace shadowkit
