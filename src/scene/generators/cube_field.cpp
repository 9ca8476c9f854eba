// Thakur, Cheng & Miura §9 ("Scalability"): N cubes in a scene of constant total volume, so
// the cubes get smaller as N grows, generated back to front (the RE-loops paper's worst case:
// every face is scan-converted and looked up).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "builtin_scenes.h"
#include "primitives.h"

namespace shadowkit::generators {
namespace {

// The fixed volume the cubes fill, above the ground plane y = 0.
constexpr Vec3 kFieldLo{-5, 0.5, -5};
constexpr double kFieldSize = 10;
constexpr std::int64_t kMaxCubes = 100000;
constexpr double kGroundHalf = 40;

// View from the front right and above; the light is high on the front left, outside the
// volume, so the shadows fall to the right onto the visible ground.
constexpr Vec3 kCamera{11.5, 13, 22};
constexpr Vec3 kLookAt{4.5, 4.4, 0.5};
constexpr Vec3 kLight{-24, 30, 9};

/// \brief SplitMix64 (Steele, Lea & Flood 2014): a tiny PRNG whose output is fixed by the
/// seed on every platform, unlike the standard library's distributions.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ULL;
    return mix(state_);
  }
  /// Uniform in [lo, hi) from the top 53 bits.
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
  }
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t state_;
};

/// The smallest k with k³ >= count (integer arithmetic: std::cbrt may round below).
int slots_per_axis(std::int64_t count) {
  int k = 1;
  while (std::int64_t(k) * k * k < count) ++k;
  return k;
}

/// \brief One cell of the k × k × k grid that partitions the volume.
struct Slot {
  std::uint32_t index;  ///< i + k (j + k l)
  Vec3 center;
};

/// All slots, farthest from the camera first; ties keep the grid order.
std::vector<Slot> slots_back_to_front(int k) {
  const double size = kFieldSize / k;
  std::vector<Slot> slots;
  slots.reserve(std::size_t(k) * k * k);
  for (int l = 0; l < k; ++l) {
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < k; ++i) {
        const Vec3 center = kFieldLo + Vec3{(i + 0.5) * size, (j + 0.5) * size, (l + 0.5) * size};
        slots.push_back({std::uint32_t(i + k * (j + k * l)), center});
      }
    }
  }
  const auto distance2 = [](const Slot& s) { return dot(s.center - kCamera, s.center - kCamera); };
  std::stable_sort(slots.begin(), slots.end(),
                   [&](const Slot& a, const Slot& b) { return distance2(a) > distance2(b); });
  return slots;
}

/// A cube of edge slot/2 in \p slot with a small rotation and jitter drawn from \p seed.
/// Its half extent along any axis is at most (√3/4 + 0.06) slot < slot/2: it stays in the slot.
void add_jittered_cube(PolygonSoup& soup, const Slot& slot, double slot_size, std::uint64_t seed) {
  SplitMix64 rng(SplitMix64::mix(seed ^ SplitMix64::mix(slot.index + 1)));
  // The quaternion (1, a, b, c) with |a|, |b|, |c| <= 0.15 turns by at most about 29°.
  const double a = rng.uniform(-0.15, 0.15);
  const double b = rng.uniform(-0.15, 0.15);
  const double c = rng.uniform(-0.15, 0.15);
  const double jitter = 0.06 * slot_size;
  const Vec3 offset{rng.uniform(-jitter, jitter), rng.uniform(-jitter, jitter),
                    rng.uniform(-jitter, jitter)};
  const double half = slot_size / 4;
  add_oriented_box(soup, slot.center + offset, {half, half, half},
                   rotation_from_quaternion(1, a, b, c));
}

}  // namespace

SceneParts cube_field_scene(const ParamReader& params) {
  params.allow_only({"count", "seed"});
  const std::int64_t count = params.integer("count", 125, 1, kMaxCubes);
  const std::uint64_t seed = params.seed("seed", 1);

  const int k = slots_per_axis(count);
  const std::vector<Slot> slots = slots_back_to_front(k);
  GeneratedObject cubes{"cubes", {}};
  cubes.soup.positions.reserve(std::size_t(count) * 8);
  for (std::int64_t n = 0; n < count; ++n) {
    add_jittered_cube(cubes.soup, slots[std::size_t(n)], kFieldSize / k, seed);
  }

  SceneParts parts;
  parts.objects.push_back(std::move(cubes));
  parts.objects.push_back(ground_object(kGroundHalf));
  parts.lights.push_back(Light::point(kLight));
  parts.camera = camera_looking_at(kCamera, kLookAt);
  return parts;
}

}  // namespace shadowkit::generators
