#pragma once
// A scratch directory with a ground mesh, and a valid scene file text to vary one part of.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {

namespace fs = std::filesystem;

class SceneFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("shadowkit_scene_file_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    write("ground.obj", "v -5 0 -5\nv 5 0 -5\nv 5 0 5\nv -5 0 5\nf 1 4 3 2\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }

  // A valid scene with one substitution applied.
  std::string scene(const std::string& camera = R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                    const std::string& lights = R"({"type": "point", "position": [3, 10, 4]})",
                    const std::string& objects = R"({"mesh": "ground.obj"})") {
    return "{\n  \"camera\": {" + camera + ", \"width\": 64, \"height\": 48},\n  \"lights\": [" +
           lights + "],\n  \"objects\": [" + objects + "]\n}\n";
  }

  std::string error_of(const std::string& text) {
    const fs::path p = write("scene.json", text);
    try {
      load_scene_file(p, quiet_);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path dir_;
  Context quiet_{0, [](const std::string&) {}};
};

}  // namespace shadowkit
