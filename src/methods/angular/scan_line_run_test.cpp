#include "scan_line_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

// A receiver through the origin tilted against the scan lines, so theta changes along them.
const Plane kGround{normalize(Vec3{0.6, 1, 0.2}), 0};
// The horizontal ground: its scan lines are constant-theta lines.
const Plane kFlat{{0, 1, 0}, 0};

// The visible point of \p plane at pixel (c, row), from the contract's ray.
Vec3 ground_point(const Camera& cam, int c, int row, const Plane& plane = kGround) {
  const Vec3 d = cam.pixel_ray(c, row);
  return cam.position + d * (-plane.distance(cam.position) / dot(plane.normal, d));
}

struct Case {
  Light light;
  ThetaQuantization q;
};

std::vector<Case> cases() {
  ThetaQuantization turn{-std::numbers::pi, 2 * std::numbers::pi / 3000, 3000, true};
  ThetaQuantization parallel{-20, 0.013, 3000, false};
  // The last light travels along the camera's right axis (+x): its theta-planes also hold
  // the camera's forward axis.
  return {{Light::point({1, 5, 2}), turn},
          {Light::point({-3, 2, -4}), turn},
          {Light::directional({0.4, -1, -0.3}), parallel},
          {Light::directional({1, 0, 0}), parallel}};
}

TEST(ScanLineRun, VisiblePointsFollowThePixelRays) {
  const Camera cam = testing::camera({0, 4, 8}, {0, 0, 0}, 200, 100);
  for (const Case& test : cases()) {
    const LightFrame frame(test.light, cam, {});
    const ScanLineRun run(frame, cam, kGround, 70);
    for (int c : {0, 57, 199}) {
      const Vec3 expected = frame.local(ground_point(cam, c, 70));
      EXPECT_NEAR(length(run.local(c) - expected), 0, 1e-12);
    }
  }
}

// Eq. 7: the run ends where theta first leaves its entry, as found pixel by pixel.
TEST(ScanLineRun, MaximumRunLengthAgreesWithBruteForce) {
  const Camera cam = testing::camera({0, 4, 8}, {0, 0, 0}, 400, 200);
  int compared = 0;
  for (const Case& test : cases()) {
    const LightFrame frame(test.light, cam, {});
    const ThetaBoundaries bounds(frame, test.q);
    for (int row = 110; row < 200; row += 7) {
      const ScanLineRun run(frame, cam, kGround, row);
      for (int c0 = 0; c0 < 400; c0 += 13) {
        const int k = test.q.index(frame.angular(ground_point(cam, c0, row)).theta);
        int brute = c0 + 1;
        while (brute < 400 &&
               test.q.index(frame.angular(ground_point(cam, brute, row)).theta) == k) {
          ++brute;
        }
        const double end = max_run_end(run, bounds, k, c0);
        const int predicted = int(std::min(std::ceil(end), 400.0));
        EXPECT_EQ(predicted, brute) << "row " << row << " c0 " << c0;
        compared += brute < 400;
      }
    }
  }
  EXPECT_GT(compared, 100);
}

// xEquivalentOf (Sec. 7): the column where phi reaches a value, against pixel stepping.
TEST(ScanLineRun, PhiCrossingAgreesWithBruteForce) {
  const Camera cam = testing::camera({0, 4, 8}, {0, 0, 0}, 400, 200);
  int compared = 0;
  for (const Case& test : cases()) {
    for (const Plane& plane : {kGround, kFlat}) {
      const LightFrame frame(test.light, cam, {});
      for (int row = 110; row < 200; row += 11) {
        const ScanLineRun run(frame, cam, plane, row);
        const auto phi_at = [&](int c) {
          return frame.angular(ground_point(cam, c, row, plane)).phi;
        };
        const double phi0 = phi_at(10), phi1 = phi_at(390);
        // A scan line along the light's rays (kFlat's, under the light along the right axis)
        // keeps phi.
        if (std::abs(phi1 - phi0) < 1e-9) continue;
        for (double t : {0.1234, 0.3771, 0.8123}) {  // columns off the pixel centres
          const double target = phi0 + t * (phi1 - phi0);
          int brute = 11;
          while ((phi_at(brute) - target) * (phi1 - phi0) < 0) {
            ++brute;
          }
          EXPECT_EQ(int(std::ceil(run.phi_crossing(target, 10))), brute) << "row " << row;
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 20);
}

// phi's direction along the run, in closed form, against the next pixel's phi.
TEST(ScanLineRun, PhiDirectionAgreesWithTheNextPixel) {
  const Camera cam = testing::camera({0, 4, 8}, {0, 0, 0}, 400, 200);
  int compared = 0;
  for (const Case& test : cases()) {
    const LightFrame frame(test.light, cam, {});
    for (const Plane& plane : {kGround, kFlat}) {
      for (int row = 110; row < 200; row += 17) {
        const ScanLineRun run(frame, cam, plane, row);
        for (int c = 0; c + 1 < 400; c += 23) {
          const double here = frame.angular(ground_point(cam, c, row, plane)).phi;
          const double next = frame.angular(ground_point(cam, c + 1, row, plane)).phi;
          if (std::abs(next - here) < 1e-12) continue;
          EXPECT_EQ(run.phi_increasing(c), next > here) << "row " << row << " c " << c;
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 100);
}

// The entry found from a nearby entry by the boundary planes' sides is eq. 2's, as long as
// the guess is within reach; a guess out of reach or unknown falls back to eq. 2.
TEST(ThetaBoundaries, LocateAgreesWithTheArctangent) {
  const Camera cam = testing::camera({0, 4, 8}, {0, 0, 0}, 400, 200);
  int compared = 0;
  for (const Case& test : cases()) {
    const LightFrame frame(test.light, cam, {});
    const ThetaBoundaries bounds(frame, test.q);
    for (int row = 100; row < 200; row += 9) {
      for (int c = 0; c < 400; c += 37) {
        const Vec3 v = frame.local(ground_point(cam, c, row));
        const int k = test.q.index(frame.angular_local(v).theta);
        for (const int guess : {-2, k - 3, k - 1, k, k + 2, k + 40}) {
          EXPECT_EQ(test.q.entry(bounds.locate(v, guess)), test.q.entry(k)) << guess;
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 500);
}

}  // namespace
}  // namespace shadowkit::angular
