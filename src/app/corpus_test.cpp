// Every file of Debian's assimp-testmodels, judged against assimp's own tool (`assimp info
// FILE -r`, assimp-utils): a file it loads with polygons loads in shadowkit with the same
// count and renders with raytrace; a file it refuses, or that holds no polygons, shadowkit
// refuses with one line. Nothing may crash or hang. Prints a summary per format, and writes
// it as Markdown to $SHADOWKIT_CORPUS_SUMMARY when that is set (scripts/corpus-summary.sh).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "shadowkit/app/pipeline.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/mesh_io.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = "/usr/share/assimp/models";

// Files assimp loads with polygons that shadowkit refuses on purpose: their geometry is
// invalid, and assimp reads past it. The value is what shadowkit's message must say.
const std::map<std::string, std::string> kInvalidGeometry = {
    {"OBJ/number_formats.obj", "expected a z coordinate, found '3.1+e2'"},
    {"OFF/invalid.off", "face 1 has vertex index 20 out of range (the file has 3 vertices)"},
    {"invalid/OutOfMemory.off", "declares 353535235358 vertices"},
    {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "is not finite once placed"},
    {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "index 255 is out of range"},
    // assimp reads these UTF-16 copies of ThreeCubesGreen.ASE with every vertex at the origin.
    {"ASE/ThreeCubesGreen_UTF16BE.ASE", "all 8 of its polygons are degenerate"},
    {"ASE/ThreeCubesGreen_UTF16LE.ASE", "all 8 of its polygons are degenerate"},
};

/// \brief What `assimp info FILE -r` says of a file.
struct AssimpVerdict {
  bool loads = false;     ///< exit status 0 and a face count
  std::size_t faces = 0;  ///< every primitive: polygons, lines and points
  bool polygons = false;  ///< its primitive types include triangles or polygons
  std::string error;
};

std::string shell_quoted(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

AssimpVerdict assimp_info(const fs::path& file) {
  const std::string command = "timeout 60 assimp info " + shell_quoted(file.string()) + " -r 2>&1";
  std::FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return {false, 0, false, "cannot run assimp"};
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    output.append(buffer, n);
  const int status = pclose(pipe);
  AssimpVerdict verdict;
  std::smatch m;
  if (std::regex_search(output, m, std::regex(R"(\nFaces:\s+(\d+))"))) {
    verdict.faces = std::stoull(m[1]);
    verdict.loads = status == 0;
  }
  if (std::regex_search(output, m, std::regex(R"(\nPrimitive Types:\s*([^\n]*))"))) {
    verdict.polygons = m[1].str().find("triangles") != std::string::npos ||
                       m[1].str().find("n-polygons") != std::string::npos;
  }
  if (std::regex_search(output, m, std::regex(R"(ERROR: ([^\n]*))"))) verdict.error = m[1];
  return verdict;
}

/// \brief One file's outcome, for the summary.
struct Outcome {
  std::string format;
  bool assimp_loads = false;
  bool loaded = false;
  std::string refusal;
};

std::string format_of(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext.empty() ? "(no extension)" : ext;
}

// The surface pixels of raytrace's mask at a small size; the camera frames the whole mesh, but
// a few tiny, far-apart triangles may fall between the centres of fewer pixels.
std::size_t surface_pixels(Scene scene) {
  scene.camera.width = 192;
  scene.camera.height = 108;
  const Context quiet{.threads = 0, .warn = [](const std::string&) {}};
  const CameraPass pass = run_camera_pass(scene, {}, quiet);
  const std::vector<MethodRun> runs =
      run_method(scene, pass.surfaces, "raytrace", {}, {}, quiet, OnFailure::stop);
  return runs.empty()
             ? 0
             : std::size_t(std::count_if(runs[0].mask.pixels.begin(), runs[0].mask.pixels.end(),
                                         [](std::uint8_t v) { return v != kMaskBackground; }));
}

Outcome judge(const fs::path& file) {
  const std::string name = fs::relative(file, kCorpus).string();
  SCOPED_TRACE(name);
  const AssimpVerdict assimp = assimp_info(file);
  const bool assimp_loads = assimp.loads && assimp.faces > 0 && assimp.polygons;
  const auto invalid = kInvalidGeometry.find(name);
  Outcome outcome{format_of(file), assimp_loads, false, ""};
  const Context quiet{.threads = 0, .warn = [](const std::string&) {}};
  try {
    MeshFile mesh = read_mesh_file(file, quiet);
    if (assimp.loads) {
      EXPECT_EQ(mesh.stored_polygons + mesh.skipped_primitives, assimp.faces)
          << mesh.stored_polygons << " polygons and " << mesh.skipped_primitives
          << " points and lines, against assimp's faces";
    }
    Scene scene = mesh_scene(std::move(mesh), file, quiet);
    outcome.loaded = true;
    EXPECT_EQ(invalid, kInvalidGeometry.end()) << "loads, but its geometry is invalid";
    EXPECT_GT(surface_pixels(std::move(scene)), 0u) << "raytrace sees none of it";
  } catch (const InputError& e) {
    outcome.refusal = e.what();
    EXPECT_THAT(outcome.refusal, ::testing::Not(::testing::HasSubstr("\n")));
    EXPECT_THAT(outcome.refusal, ::testing::HasSubstr(file.string()));
    if (invalid != kInvalidGeometry.end()) {
      EXPECT_THAT(outcome.refusal, ::testing::HasSubstr(invalid->second));
    } else {
      EXPECT_FALSE(assimp_loads) << "assimp loads it with " << assimp.faces << " faces";
    }
  }
  return outcome;
}

/// \brief Files tried, loaded by assimp, loaded by shadowkit, per format.
struct Tally {
  int tried = 0, assimp = 0, shadowkit = 0, both = 0;
};

void report(const std::vector<Outcome>& outcomes) {
  std::map<std::string, Tally> formats;
  Tally all;
  for (const Outcome& o : outcomes) {
    for (Tally* t : {&formats[o.format], &all}) {
      ++t->tried;
      t->assimp += o.assimp_loads;
      t->shadowkit += o.loaded;
      t->both += o.assimp_loads && o.loaded;
    }
  }
  std::string table =
      "| format | files | assimp loads with polygons | shadowkit loads | both |\n"
      "|---|---:|---:|---:|---:|\n";
  for (const auto& [format, t] : formats) {
    table += "| " + format + " | " + std::to_string(t.tried) + " | " + std::to_string(t.assimp) +
             " | " + std::to_string(t.shadowkit) + " | " + std::to_string(t.both) + " |\n";
  }
  table += "| all | " + std::to_string(all.tried) + " | " + std::to_string(all.assimp) + " | " +
           std::to_string(all.shadowkit) + " | " + std::to_string(all.both) + " |\n";
  std::map<std::string, int> reasons;
  for (const Outcome& o : outcomes) {
    if (o.loaded) continue;
    // The reason without the file's path: what follows the location.
    std::string reason = o.refusal.substr(o.refusal.find(": ") + 2);
    reason = std::regex_replace(reason, std::regex(kCorpus.string() + R"(/\S*)"), "FILE");
    reason = std::regex_replace(reason, std::regex(R"(\d+)"), "N");
    reason = std::regex_replace(reason, std::regex(R"(".*")"), "\"...\"");
    ++reasons[reason.substr(0, 110)];
  }
  std::string refusals = "| refusals | files |\n|---|---:|\n";
  for (const auto& [reason, n] : reasons) {
    std::string cell = reason;
    for (char& c : cell) c = c == '|' ? '/' : c;
    refusals += "| " + cell + " | " + std::to_string(n) + " |\n";
  }
  std::printf("%s\n%s", table.c_str(), refusals.c_str());
  if (const char* path = std::getenv("SHADOWKIT_CORPUS_SUMMARY")) {
    std::ofstream(path) << table << "\n" << refusals;
  }
}

TEST(Corpus, RealFilesLoadAsAssimpLoadsThemAndRender) {
  ASSERT_TRUE(fs::is_directory(kCorpus)) << "scripts/install-deps.sh installs assimp-testmodels";
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GT(files.size(), 500u);
  std::vector<Outcome> outcomes;
  for (const fs::path& file : files) outcomes.push_back(judge(file));
  report(outcomes);
}

}  // namespace
}  // namespace shadowkit
