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

/// \brief Eq. 4's unit where shadows fall: the theta of one entry of the automatic R.
/// On every face whose seen side the light faces (contract condition 1: the others are in
/// shadow whatever the table says), cut to the view, the theta of a pixel is the norm of
/// theta's gradient across the image there. Its harmonic mean over those faces' screen area
/// (occlusion ignored; large faces integrated in pieces) is the theta of an entry that spans
/// one pixel on average over their pixels; the entry is entries_per_pixel(that area) times
/// finer. Points the light grazes (sine below kGrazingSine) are left out: the exact re-check
/// answers there. 0 when no such face is in view.
double entry_theta(const Scene& scene, const LightFrame& frame);

/// Entries per pixel at kReferencePixels pixels of receivers.
inline constexpr double kEntriesPerPixel = 3;
/// A 320 x 240 image's pixels.
inline constexpr double kReferencePixels = 320 * 240;
/// Entries per pixel on receivers of any size: one entry spans at most two pixels.
inline constexpr double kLeastEntriesPerPixel = 0.5;
/// The automatic R's bound.
inline constexpr int kMostAutomaticEntries = 32768;

/// \brief Entries per pixel of the automatic R on receivers of \p pixels screen pixels:
/// kEntriesPerPixel * sqrt(kReferencePixels / pixels), at least kLeastEntriesPerPixel. A pair
/// cut at its entry's centre moves a shadow's edge by up to half an entry, so the pixels that
/// differ from the exact shadow lie in bands along the shadows' edges, of a width in pixels
/// proportional to the entry's theta over a pixel's. Their share of the receivers' pixels is
/// the edges' length in pixels over the area in pixels, which for the same view grows as one
/// over the square root of the area: an entry's theta that keeps the share is then the same
/// at any image size, and the same on a view's small receivers as on a large one.
double entries_per_pixel(double pixels);

/// \brief Eq. 4 generalized: R such that an entry spans \p entry (entry_theta) over
/// \p theta_range, at most kMostAutomaticEntries; the number of scan lines when no receiver
/// is in view.
int automatic_resolution(const Scene& scene, double entry, double theta_range);

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
