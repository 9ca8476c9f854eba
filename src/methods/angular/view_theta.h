#pragma once
// Eq. 4's inputs taken from the view volume (discretized-shadow-volume paper, Sec. 3): "this
// range is computed at the set up time based on the view volume".
#include <span>

#include "light_frame.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::angular {

/// \brief The theta the camera can see: every visible point lies in the view frustum and in
/// the scene's bounding box, so its theta lies in [lo, hi] unless \p bounded is false (the
/// light's X axis passes through that region, or it wraps past theta = +-pi).
struct ViewTheta {
  double lo = 0, hi = 0;
  bool bounded = false;
};

/// The theta range of the scene's bounding box clipped to the view frustum.
ViewTheta view_theta(const Scene& scene, const LightFrame& frame);

/// Eq. 4's unit: the theta of one scan line at three quarters of the scene vertices in view
/// (a quartile of their per-vertex steps); 0 when no vertex is in view.
double scan_line_theta(const Scene& scene, const LightFrame& frame);

/// \brief Eq. 4 generalized: R such that one entry is no coarser than one scan line (Sec. 3:
/// "at the limiting range there is a unique theta value for each scan line"), \p scan_line
/// as scan_line_theta gives it, over \p theta_range, at most 8 per scan line of the image;
/// the number of scan lines when no vertex is in view.
int automatic_resolution(const Scene& scene, double scan_line, double theta_range);

/// Eq. 4's Z_f as written: the depth -Z of the vertex in view farthest from the light,
/// counted in scan lines at that vertex (the paper's coordinates are the screen's); 0 when
/// no vertex is in view.
double farthest_depth(const Scene& scene, const LightFrame& frame);

/// \brief Eq. 4 as written: R = Z_f (tan theta_max - tan theta_min), \p z_f as
/// farthest_depth gives it, over the table's [theta_lo, theta_hi]; for a directional light
/// the number of scan lines (Sec. 3: "if the light source is far away"). Where the range
/// reaches theta = +-pi/2, tan diverges (Sec. 11.2's reason for a variable resolution): R is
/// then the cap, 8 per scan line of the image, as it is wherever eq. 4 exceeds it.
int eq4_resolution(const Scene& scene, double z_f, double theta_lo, double theta_hi,
                   bool point_light);

}  // namespace shadowkit::angular
