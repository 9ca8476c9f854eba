#include "loop_slicer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "loops_in_frame_testing.h"
#include "occluders.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::angular {
namespace {

// The pairs of \p out in entry \p k, in their order.
std::vector<EntryPair> in_entry(const std::vector<EntryPair>& out, std::uint32_t k) {
  std::vector<EntryPair> pairs;
  std::copy_if(out.begin(), out.end(), std::back_inserter(pairs),
               [k](const EntryPair& p) { return p.entry == k; });
  return pairs;
}

// Consecutive entries mostly walk the same faces: a walk reuses the previous entry's exits
// and, when it repeats the whole path, is replayed from its edges. Either way every entry's
// pairs must be bit for bit those of walks made afresh, one entry at a time.
void expect_entries_as_sliced_alone(const std::string& spec) {
  const Scene scene = load_scene(spec, {});
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    const LightFrame frame(scene.lights[light], scene.camera, scene.bounds().center());
    const std::vector<FarSheets> sheets = occluding_sheets(scene, scene.lights[light]);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
      const Mesh& mesh = scene.objects[o].mesh;
      const LoopsInFrame in_frame(mesh, sheets[o], frame);
      if (in_frame.loops.empty()) continue;
      constexpr int kEntries = 600;  // many entries per ridge edge: long runs of one path
      const ThetaQuantization q = in_frame.quantization(kEntries);
      const std::vector<ThetaSlice> slices = slices_of(q, frame.point_light());
      const SlicedMesh m{mesh, sheets[o], in_frame.local, in_frame.theta, in_frame.hidden_id};
      SliceScratch scratch;
      for (const RidgeEdgeLoop& loop : in_frame.loops) {
        std::vector<EntryPair> all;
        slice_loop(m, in_frame.ridges, loop, q, slices, scratch, all);
        ASSERT_FALSE(all.empty()) << spec;
        for (int k = 0; k < kEntries; ++k) {
          const ThetaQuantization one{q.lower(k), q.step, 1, false};
          std::vector<EntryPair> alone;
          slice_loop(m, in_frame.ridges, loop, one, {&slices[k], 1}, scratch, alone);
          const std::vector<EntryPair> found = in_entry(all, std::uint32_t(k));
          ASSERT_EQ(found.size(), alone.size()) << spec << " light " << light << " entry " << k;
          for (std::size_t i = 0; i < found.size(); ++i) {
            EXPECT_EQ(found[i].hidden, alone[i].hidden);
            EXPECT_EQ(found[i].phi_begin, alone[i].phi_begin);
            EXPECT_EQ(found[i].phi_end, alone[i].phi_end);
          }
        }
      }
    }
  }
}

TEST(LoopSlicer, RepeatedWalksGiveTheirEntriesPairsBitForBit) {
  // Coils and holes (point lights), concave real-world shapes and a directional light.
  for (const char* spec : {"coil", "holed", "hole-like", "tetra:3", "cubes:30", "three-lights"}) {
    expect_entries_as_sliced_alone(spec);
  }
}

}  // namespace
}  // namespace shadowkit::angular
