#pragma once
/// \brief What one input may ask of shadowkit. Each limit is checked up front, from the input,
/// before the work or the memory it asks for (docs/scene-format.md lists them).
#include <cstddef>
#include <cstdint>

namespace shadowkit::limits {

/// Arrays and objects nested in a JSON text (scene files, glTF): far beyond any real file,
/// far below what recursive JSON code can take.
inline constexpr int kJsonDepth = 100;

/// Polygons in one scene, after tessellation and instancing: 16 times the million triangles
/// the methods are built for.
inline constexpr std::size_t kPolygons = std::size_t{1} << 24;

/// Pixels per side and per image of a camera.
inline constexpr int kImageSide = 16384;
inline constexpr std::int64_t kPixels = std::int64_t{1} << 25;  // 8K UHD fits

/// Mask pixels of all lights together: every light's mask is held at once (`render --image`
/// and `compare` shade and compare them all), one byte a pixel. 64 lights of 8K UHD, or 1,035
/// of 1920x1080, fit.
inline constexpr std::int64_t kMaskPixels = std::int64_t{1} << 31;

/// Largest absolute coordinate of a vertex, camera or light.
inline constexpr double kCoordinate = 1e15;

/// The smallest ratio of the scene's size to its largest coordinate: below it, coordinates
/// carry fewer than about five significant digits of the geometry itself.
inline constexpr double kSizeToOffset = 1e-11;
/// The smallest size of a scene's geometry: below it, coordinates are subnormal numbers with
/// too few bits to describe it.
inline constexpr double kSmallestSize = 1e-290;

/// Segments per patch edge of a Catmull-Clark object's tessellation.
inline constexpr int kTessellation = 256;

/// Seconds an assimp import may take before it is stopped: a base and more per MiB of the
/// file, so that a large model has time and a small damaged file is stopped soon.
inline constexpr double kImportSeconds = 10;
inline constexpr double kImportSecondsPerMiB = 1;
/// Bytes of address space an assimp import may use: a base and more per byte of the file.
inline constexpr std::size_t kImportBytes = std::size_t{1} << 30;
inline constexpr std::size_t kImportBytesPerFileByte = 64;

}  // namespace shadowkit::limits
