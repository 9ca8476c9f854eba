#include "shadow_generator.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "shadowkit/core/error.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::svbsp {
namespace {

// The distance within which a point counts as on a shadow plane, relative to how far the
// planes reach across the scene.
double plane_tolerance(const Scene& scene, const Light& light) {
  const double size = std::max(1.0, scene.bounds().diagonal());
  const double reach = light.type == Light::Type::point
                           ? size + length(light.position - scene.bounds().center())
                           : size;
  return SceneBsp::kRelativeTolerance * reach;
}

// Hazard: one tolerance for "the light is in the face's plane", as for every plane test.
double in_plane_tolerance(const Scene& scene, const Light& light) {
  return light.type == Light::Type::point ? plane_tolerance(scene, light)
                                          : SceneBsp::kRelativeTolerance;
}

// Pieces sampled to place the cells of a balanced tree.
constexpr std::size_t kCellSample = std::size_t(1) << 16;

}  // namespace

ShadowedWhole far_side_of(const Scene& scene, const Light& light) {
  const OutwardSolids& solids = scene.outward_solids();
  if (light.type == Light::Type::point) {
    return [&solids, &scene, p = light.position](std::uint32_t face) {
      return solids.far_side_from(scene, face, p);
    };
  }
  return [&solids, &scene, d = light.direction](std::uint32_t face) {
    return solids.far_side_along(scene, face, d);
  };
}

FrontFacing front_facing(const Scene& scene, const Light& light) {
  const double in_plane = in_plane_tolerance(scene, light);
  FrontFacing count;
  for (const SceneObject& object : scene.objects) {
    for (std::size_t f = 0; f < object.mesh.face_count(); ++f) {
      if (light_side(object.mesh.planes[f], light) <= in_plane) continue;
      ++count.polygons;
      count.edges += object.mesh.face_size(f);
    }
  }
  return count;
}

ShadowGenerator::ShadowGenerator(const Scene& scene, const Light& light,
                                 const GeneratorSettings& settings, ShadowedWhole shadowed_whole,
                                 const ConvexSolids* solids, const SplitPolygons* split)
    : scene_(scene),
      light_(light),
      settings_(settings),
      shadowed_whole_(std::move(shadowed_whole)),
      solids_(solids),
      in_plane_(in_plane_tolerance(scene, light)),
      tree_(light, plane_tolerance(scene, light), settings.merge_siblings,
            settings.skip_edges_in_tree, split) {}

void ShadowGenerator::divide(std::span<const ConvexPolygon> pieces) {
  std::size_t levels = 0;
  while ((pieces.size() >> (levels + 1)) >= kPiecesPerCell) ++levels;
  if (!settings_.balance || levels == 0) return;
  const std::optional<LightView> view = LightView::of(light_, scene_.bounds());
  if (!view) return;
  // The medians of an evenly spread sample place the cells as well as those of all.
  const std::size_t n = std::min(pieces.size(), kCellSample);
  std::vector<LightView::Coordinates> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    points[i] = view->coordinates(centroid(pieces[i * pieces.size() / n]));
  }
  tree_.divide(*view, points, levels);
}

bool ShadowGenerator::in_light_plane(const ConvexPolygon& piece) const {
  return std::abs(light_side(scene_.face_plane(piece.face), light_)) <= in_plane_;
}

bool ShadowGenerator::turned_to_light(std::uint32_t face) const {
  return light_side(scene_.face_plane(face), light_) > in_plane_;
}

bool ShadowGenerator::facing(const ConvexPolygon& piece) const {
  return settings_.two_sided ? !in_light_plane(piece) : turned_to_light(piece.face);
}

void ShadowGenerator::keep_whole_if_uniform(const ConvexPolygon& piece, std::size_t first,
                                            std::vector<Fragment>& out) const {
  if (!settings_.whole_pieces || out.size() - first < 2) return;
  const bool lit = out[first].lit;
  const bool uniform = std::all_of(out.begin() + std::ptrdiff_t(first), out.end(),
                                   [lit](const Fragment& f) { return f.lit == lit; });
  if (!uniform) return;
  out.resize(first);
  out.push_back({piece, lit});
}

void ShadowGenerator::process(NodePieces node, std::vector<Fragment>& out) {
  process_node(node, out);
  for (const ConvexPolygon& piece : node.pieces) tree_.piece_done(piece);
}

void ShadowGenerator::process_node(NodePieces node, std::vector<Fragment>& out) {
  if (node.solid < 0) return process_coplanar(node.pieces, out);
  const std::size_t solid = std::size_t(node.solid);
  // A convex solid is a unit only for a light outside it, which some face then turns to.
  const bool outside =
      std::any_of(node.pieces.begin(), node.pieces.end(),
                  [this](const ConvexPolygon& p) { return turned_to_light(p.face); });
  if (outside) return process_solid(node.pieces, solid, out);
  // From inside, its faces hide none of one another: in any order, each alone.
  for (const ConvexPolygon& piece : node.pieces) process_coplanar({&piece, 1}, out);
}

ShadowGenerator::Coplanar ShadowGenerator::coplanar_pieces(
    std::span<const ConvexPolygon> coplanar) const {
  const auto whole = std::count_if(coplanar.begin(), coplanar.end(),
                                   [this](const ConvexPolygon& p) { return shadowed_whole(p); });
  return {whole > 0, std::ssize(coplanar) - whole > 1};
}

bool ShadowGenerator::filtered(const ConvexPolygon& piece, const Coplanar& coplanar) const {
  return !(coplanar.any_whole && shadowed_whole(piece)) && facing(piece);
}

void ShadowGenerator::process_coplanar(std::span<const ConvexPolygon> coplanar,
                                       std::vector<Fragment>& out) {
  const Coplanar pieces = coplanar_pieces(coplanar);
  const bool together = pieces.together;
  const std::size_t group = out.size();
  for (const ConvexPolygon& piece : coplanar) {
    const std::size_t first = out.size();
    if (!filtered(piece, pieces)) {
      out.push_back({piece, false});  // Fig. 3: not facing the light, or shadowed whole
      continue;
    }
    ++light_facing_;
    if (together)
      tree_.classify(piece, out);
    else
      tree_.determine_shadow(piece, out);
    keep_whole_if_uniform(piece, first, out);
  }
  if (!together) return;
  for (std::size_t i = group; i < out.size(); ++i) {
    if (out[i].lit) tree_.enlarge(out[i].polygon);
  }
}

void ShadowGenerator::process_solid(std::span<const ConvexPolygon> faces, std::size_t solid,
                                    std::vector<Fragment>& out) {
  // §6, contour edges only: the faces turned to the light are classified first, none
  // hiding another; the solid's own near side shadows the rest, which casts nothing.
  SHADOWKIT_CHECK(solids_ != nullptr);
  std::vector<Landing> landings;
  for (const ConvexPolygon& piece : faces) {
    const std::size_t first = out.size();
    if (!turned_to_light(piece.face)) {
      out.push_back({piece, false});
      continue;
    }
    ++light_facing_;
    tree_.classify(piece, out, &landings);
    keep_whole_if_uniform(piece, first, out);
  }
  tree_.enlarge_by_contour(std::move(landings),
                           solids_->contour_planes(solid, light_, [this](std::uint32_t f) {
                             return turned_to_light(f);
                           }));
}

LightFragments generate_shadows(const SceneBsp& bsp, const Scene& scene, const Light& light,
                                const GeneratorSettings& settings,
                                const ShadowedWhole& shadowed_whole, const ConvexSolids* solids,
                                std::vector<Fragment> storage) {
  ShadowGenerator generator(scene, light, settings, shadowed_whole, solids);
  generator.divide(bsp.pieces());
  LightFragments result;
  result.fragments = std::move(storage);
  result.fragments.clear();
  if (settings.cells_in_parallel && generator.tree().cell_count() > 1 && solids == nullptr) {
    generator.process_in_cells(bsp, result.fragments);
  } else {
    bsp.front_to_back(light, [&](NodePieces node) { generator.process(node, result.fragments); });
  }
  result.light_facing = generator.light_facing();
  result.svbsp_nodes = generator.svbsp_nodes();
  result.svbsp_bytes = generator.svbsp_bytes();
  return result;
}

}  // namespace shadowkit::svbsp
