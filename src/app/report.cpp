#include "shadowkit/app/report.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "shadowkit/app/html.h"
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

std::string failure_caption(const MethodRun& run) {
  return "<figure><figcaption class=\"failed\">" + run.method +
         " failed: " + html_escaped(run.failure) + "</figcaption></figure>\n";
}

// A table row: times, memory and mismatch; or why there are none.
std::string table_row(const MethodRun& run, const std::optional<MaskComparison>& c) {
  std::string row = "<tr><td>" + run.method + "</td><td>L" + std::to_string(run.light) + "</td>";
  if (run.failed()) {
    return row + "<td colspan=\"5\" class=\"failed\">failed: " + html_escaped(run.failure) +
           "</td></tr>\n";
  }
  row += "<td>" + format("%.2f", run.build_ms) + "</td><td>" + format("%.2f", run.shade_ms) +
         "</td><td>" + format("%.1f", double(run.memory_bytes) / 1e6) + "</td>";
  if (!c) return row + "<td colspan=\"2\" class=\"failed\">no reference</td></tr>\n";
  return row + "<td>" + format("%.4f", c->raw_pct()) + "</td><td>" +
         format("%.4f", c->interior_pct()) + "</td></tr>\n";
}

bool all_ran(const ComparedMethod& m) {
  return std::none_of(m.runs.begin(), m.runs.end(), [](const MethodRun& r) { return r.failed(); });
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
    for (std::size_t l = 0; l < m.runs.size(); ++l) {
      rows += table_row(m.runs[l], m.against_reference[l]);
    }
    // The shaded image takes every light's mask.
    if (!all_ran(m)) continue;
    write_png(dir / (m.name + ".png"), shade_image(scene, pass.surfaces, masks_of(m.runs)));
    shaded += figure(m.name + ".png", m.name);
  }
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    per_light += "<h2>Light " + std::to_string(l) + "</h2>\n<div class=\"row\">\n";
    for (const ComparedMethod& m : methods) {
      const MethodRun& run = m.runs[l];
      if (run.failed()) {
        per_light += failure_caption(run);
        continue;
      }
      const std::string stem = m.name + ".L" + std::to_string(l);
      write_png(dir / (stem + ".mask.png"), run.mask);
      per_light += figure(stem + ".mask.png", m.name + " mask");
      if (&m == &reference || !m.against_reference[l]) continue;
      write_png(dir / (stem + ".diff.png"), difference_image(reference.runs[l].mask, run.mask));
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
          "img{width:480px;border:1px solid #ccc}figcaption{text-align:center}"
          ".failed{color:#b00;text-align:left}</style>\n"
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
  html.close();  // the buffer's last bytes go out here: a full disk may show only now
  if (!html) throw InputError((dir / "index.html").string(), "cannot write the report");
}

}  // namespace shadowkit
