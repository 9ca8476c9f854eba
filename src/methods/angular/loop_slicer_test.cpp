#include "loop_slicer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "occluders.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::angular {
namespace {

// One object's RE loops in a light's frame, as AngularTable::build prepares them.
struct LoopsInFrame {
  std::vector<Vec3> local;
  std::vector<double> theta;
  std::vector<std::uint32_t> hidden_id;
  std::vector<RidgeEdge> ridges;
  std::vector<RidgeEdgeLoop> loops;

  LoopsInFrame(const Mesh& mesh, const FarSheets& sheets, const LightFrame& frame)
      : ridges(find_ridge_edges(mesh, sheets)), loops(chain_ridge_edge_loops(ridges)) {
    for (const Vec3& v : mesh.vertices) {
      local.push_back(frame.local(v));
      theta.push_back(frame.angular_local(local.back()).theta);
    }
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) hidden_id.push_back(f);
  }
};

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
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const RidgeEdge& re : in_frame.ridges) {
        lo = std::min({lo, in_frame.theta[re.from], in_frame.theta[re.to]});
        hi = std::max({hi, in_frame.theta[re.from], in_frame.theta[re.to]});
      }
      constexpr int kEntries = 600;  // many entries per ridge edge: long runs of one path
      const ThetaQuantization q{lo, (hi - lo) / kEntries, kEntries, false};
      std::vector<ThetaSlice> slices;
      for (int k = 0; k < kEntries; ++k) {
        slices.push_back(ThetaSlice::at(q.centre(k), frame.point_light(), std::uint32_t(k)));
      }
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
