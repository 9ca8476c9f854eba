#include "shadowkit/app/report.h"

#include <cstdio>
#include <fstream>

#include "shadowkit/app/shading.h"
#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;

std::string format(const char* fmt, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, value);
  return buf;
}

std::string figure(const std::string& file, const std::string& caption) {
  return "<figure><img src=\"" + file + "\" loading=\"lazy\"><figcaption>" + caption +
         "</figcaption></figure>\n";
}

}  // namespace

void write_report(const fs::path& dir, const Scene& scene, const CameraPass& pass,
                  const std::vector<ComparedMethod>& methods) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string(), "cannot create the report directory: " + ec.message());
  const ComparedMethod& reference = methods.front();

  std::string rows, shaded, per_light;
  for (const ComparedMethod& m : methods) {
    std::vector<const ShadowMask*> masks;
    for (const MethodRun& run : m.runs) masks.push_back(&run.mask);
    write_png(dir / (m.name + ".png"), shade_image(scene, pass.surfaces, masks));
    shaded += figure(m.name + ".png", m.name);
    for (std::size_t l = 0; l < m.runs.size(); ++l) {
      const MethodRun& run = m.runs[l];
      const MaskComparison& c = m.against_reference[l];
      rows += "<tr><td>" + m.name + "</td><td>L" + std::to_string(l) + "</td><td>" +
              format("%.2f", run.build_ms) + "</td><td>" + format("%.2f", run.shade_ms) +
              "</td><td>" + format("%.1f", double(run.memory_bytes) / 1e6) + "</td><td>" +
              format("%.4f", c.raw_pct()) + "</td><td>" + format("%.4f", c.interior_pct()) +
              "</td></tr>\n";
    }
  }
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    per_light += "<h2>Light " + std::to_string(l) + "</h2>\n<div class=\"row\">\n";
    for (const ComparedMethod& m : methods) {
      const std::string stem = m.name + ".L" + std::to_string(l);
      write_png(dir / (stem + ".mask.png"), m.runs[l].mask);
      per_light += figure(stem + ".mask.png", m.name + " mask");
      if (&m == &reference) continue;
      write_png(dir / (stem + ".diff.png"),
                difference_image(reference.runs[l].mask, m.runs[l].mask));
      per_light += figure(stem + ".diff.png", m.name + " vs " + reference.name);
    }
    per_light += "</div>\n";
  }

  std::ofstream html(dir / "index.html");
  if (!html) throw InputError((dir / "index.html").string(), "cannot write the report");
  html << "<!doctype html>\n<meta charset=\"utf-8\">\n<title>shadowkit: " << scene.name
       << "</title>\n<style>body{font-family:sans-serif;margin:2em;background:#fafafa}"
          "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px;"
          "text-align:right}.row{display:flex;flex-wrap:wrap;gap:12px}figure{margin:0}"
          "img{width:480px;border:1px solid #ccc}figcaption{text-align:center}</style>\n"
       << "<h1>shadowkit compare: " << scene.name << "</h1>\n<p>" << pass.surfaces.width << "x"
       << pass.surfaces.height << ", " << scene.face_count() << " polygons, " << scene.lights.size()
       << " light(s); scan conversion " << format("%.2f", pass.scan_ms)
       << " ms. Mismatch is against <b>" << reference.name
       << "</b>; interior pixels have a uniform 3x3 neighbourhood (mask and object) in the "
          "reference. Difference images: red = shadow where the reference is lit, blue = lit "
          "where it is in shadow.</p>\n"
       << "<table><tr><th>method</th><th>light</th><th>build ms</th><th>shade ms</th>"
          "<th>memory MB</th><th>mismatch %</th><th>interior %</th></tr>\n"
       << rows << "</table>\n<h2>Shaded</h2>\n<div class=\"row\">\n"
       << shaded << "</div>\n"
       << per_light;
}

}  // namespace shadowkit
