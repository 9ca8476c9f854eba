#include "fraction_plot.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "markup.h"
#include "shadowkit/app/html.h"
#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

namespace chrono = std::chrono;

// The chart's frame in SVG units: the plot area and the room for axes and legend around it.
constexpr int kWidth = 960, kPlotHeight = 300;
constexpr int kLeft = 64, kRight = 24, kTop = 16, kBelow = 60, kLegendRow = 20;
constexpr int kPlotWidth = kWidth - kLeft - kRight;
constexpr std::int64_t kDay = 86400;

// Okabe & Ito's colours, told apart with every common colour-vision deficiency; the yellow,
// weakest on white, last.
constexpr std::array<const char*, 8> kLineColours{"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                  "#E69F00", "#56B4E9", "#000000", "#F0E442"};

// Tick spacings for the time axis, in seconds: the first that gives at most 8 ticks is used;
// longer spans are ticked by months.
constexpr std::array<std::int64_t, 11> kTickSeconds{
    600, 1800, 3600, 7200, 10800, 21600, 43200, kDay, 2 * kDay, 7 * kDay, 14 * kDay};

std::string coordinate(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a / b - (a % b != 0 && (a < 0) != (b < 0));
}

// How a local time is labelled: "HH:MM" for ticks within a day, "MM-DD" for ticks days apart,
// "YYYY-MM-DD" in the axis's title.
enum class Stamp { clock, month_day, date };

std::string local_label(std::int64_t local_seconds, Stamp stamp) {
  const chrono::sys_seconds t{chrono::seconds(local_seconds)};
  const auto day = chrono::floor<chrono::days>(t);
  const chrono::year_month_day ymd{day};
  const chrono::hh_mm_ss hms{t - day};
  char text[32];
  if (stamp == Stamp::date) {
    std::snprintf(text, sizeof text, "%04d-%02u-%02u", int(ymd.year()), unsigned(ymd.month()),
                  unsigned(ymd.day()));
  } else if (stamp == Stamp::month_day) {
    std::snprintf(text, sizeof text, "%02u-%02u", unsigned(ymd.month()), unsigned(ymd.day()));
  } else {
    std::snprintf(text, sizeof text, "%02d:%02d", int(hms.hours().count()),
                  int(hms.minutes().count()));
  }
  return text;
}

// The time axis's range in local standard seconds since 1970, and the study's offset to it.
struct TimeFrame {
  std::int64_t offset = 0, from = 0, to = 0;
  double x(std::int64_t local) const {
    return kLeft + double(local - from) / double(to - from) * kPlotWidth;
  }
};

double y_of(double fraction) {
  return kTop + (1 - fraction) * kPlotHeight;
}

TimeFrame time_frame(const FractionSeries& series, double utc_offset_hours) {
  TimeFrame frame;
  frame.offset = std::llround(utc_offset_hours * 3600);
  if (series.size() > 0) {
    frame.from = series.time(0).time_since_epoch().count() + frame.offset;
    frame.to = series.time(series.size() - 1).time_since_epoch().count() + frame.offset;
  }
  if (frame.to == frame.from) frame.from -= 1800, frame.to += 1800;  // one point: an hour of axis
  return frame;
}

// The plot's frame, a grid line per quarter and the fraction axis's labels and title.
std::string fraction_axis() {
  std::string svg = "<rect x=\"" + std::to_string(kLeft) + "\" y=\"" + std::to_string(kTop) +
                    "\" width=\"" + std::to_string(kPlotWidth) + "\" height=\"" +
                    std::to_string(kPlotHeight) + "\" fill=\"none\" stroke=\"#333\"/>\n";
  for (int q = 0; q <= 4; ++q) {
    const std::string y = coordinate(y_of(q / 4.0));
    svg += "<line x1=\"" + std::to_string(kLeft) + "\" y1=\"" + y + "\" x2=\"" +
           std::to_string(kLeft + kPlotWidth) + "\" y2=\"" + y + "\" stroke=\"#ddd\"/>\n";
    char text[8];
    std::snprintf(text, sizeof text, "%.2f", q / 4.0);
    svg += "<text x=\"" + std::to_string(kLeft - 6) + "\" y=\"" + y +
           "\" text-anchor=\"end\" dominant-baseline=\"middle\">" + text + "</text>\n";
  }
  return svg + "<text transform=\"translate(16 " + std::to_string(kTop + kPlotHeight / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">sunlit fraction</text>\n";
}

// The instants of the time axis's ticks, local standard seconds, at most 8: multiples of a
// spacing up to two weeks, then the first days of every 1, 2, 3, 6 or 12k months.
std::vector<std::int64_t> time_ticks(const TimeFrame& frame) {
  std::vector<std::int64_t> ticks;
  const std::int64_t span = frame.to - frame.from;
  const auto spacing = std::find_if(kTickSeconds.begin(), kTickSeconds.end(),
                                    [&](std::int64_t s) { return span / s <= 8; });
  if (spacing != kTickSeconds.end()) {
    for (std::int64_t t = floor_div(frame.from + *spacing - 1, *spacing) * *spacing; t <= frame.to;
         t += *spacing) {
      ticks.push_back(t);
    }
    return ticks;
  }
  const auto month_of = [](std::int64_t t) {
    const chrono::year_month_day ymd{
        chrono::floor<chrono::days>(chrono::sys_seconds{chrono::seconds(t)})};
    return int(ymd.year()) * 12 + int(unsigned(ymd.month())) - 1;
  };
  const int first = month_of(frame.from - 1) + 1, months = month_of(frame.to) - first + 1;
  int step = 12 * ((months + 95) / 96);
  for (const int m : {1, 2, 3, 6}) {
    if (months / m < 8) {
      step = m;
      break;
    }
  }
  for (int m = first; m <= first + months - 1; m += step) {
    const chrono::year_month_day day{chrono::year(m / 12), chrono::month(unsigned(m % 12 + 1)),
                                     chrono::day(1)};
    ticks.push_back(chrono::sys_seconds(chrono::sys_days(day)).time_since_epoch().count());
  }
  return ticks;
}

// The time axis's ticks, their labels ("HH:MM" within a day, "MM-DD" beyond) and its title.
std::string time_axis(const TimeFrame& frame, double utc_offset_hours) {
  const std::vector<std::int64_t> ticks = time_ticks(frame);
  const Stamp stamp =
      ticks.size() > 1 && ticks[1] - ticks[0] < kDay ? Stamp::clock : Stamp::month_day;
  const std::string bottom = std::to_string(kTop + kPlotHeight);
  std::string svg;
  for (const std::int64_t t : ticks) {
    const std::string x = coordinate(frame.x(t));
    svg += "<line x1=\"" + x + "\" y1=\"" + bottom + "\" x2=\"" + x + "\" y2=\"" +
           std::to_string(kTop + kPlotHeight + 5) + "\" stroke=\"#333\"/>\n";
    svg += "<text x=\"" + x + "\" y=\"" + std::to_string(kTop + kPlotHeight + 18) +
           "\" text-anchor=\"middle\">" + local_label(t, stamp) + "</text>\n";
  }
  return svg + "<text x=\"" + std::to_string(kLeft + kPlotWidth / 2) + "\" y=\"" +
         std::to_string(kTop + kPlotHeight + 38) +
         "\" text-anchor=\"middle\">local standard time (UTC" + utc_offset_text(utc_offset_hours) +
         "), " + local_label(frame.from, Stamp::date) + " to " +
         local_label(frame.to, Stamp::date) + "</text>\n";
}

std::string polygon_line(const FractionSeries& series, const TimeFrame& frame, std::size_t line) {
  std::string svg = "<polyline fill=\"none\" stroke=\"" +
                    std::string(kLineColours[line % kLineColours.size()]) +
                    "\" stroke-width=\"1.5\" points=\"";
  for (std::size_t j = 0; j < series.size(); ++j) {
    const std::int64_t t = series.time(j).time_since_epoch().count() + frame.offset;
    svg += (j ? " " : "") + coordinate(frame.x(t)) + "," + coordinate(y_of(series.value(line, j)));
  }
  return svg + "\"/>\n";
}

// Legend entries below the time axis, two to a row.
std::string legend_entry(const std::string& label, std::size_t line) {
  const int x = kLeft + int(line % 2) * (kPlotWidth / 2);
  const std::string y = std::to_string(kTop + kPlotHeight + kBelow + int(line / 2) * kLegendRow);
  return "<line x1=\"" + std::to_string(x) + "\" y1=\"" + y + "\" x2=\"" + std::to_string(x + 24) +
         "\" y2=\"" + y + "\" stroke=\"" + kLineColours[line % kLineColours.size()] +
         "\" stroke-width=\"3\"/>\n<text x=\"" + std::to_string(x + 32) + "\" y=\"" + y +
         "\" dominant-baseline=\"middle\">" + html_escaped(label) + "</text>\n";
}

}  // namespace

std::vector<std::uint32_t> largest_polygons(const Polygons& polygons, std::size_t count) {
  std::vector<std::uint32_t> rows;
  for (std::uint32_t p = 0; p < polygons.rows.size(); ++p) {
    if (polygons.rows[p].area > 0) rows.push_back(p);
  }
  const auto larger = [&](std::uint32_t a, std::uint32_t b) {
    return polygons.rows[a].area != polygons.rows[b].area
               ? polygons.rows[a].area > polygons.rows[b].area
               : a < b;
  };
  const std::size_t kept = std::min(count, rows.size());
  std::partial_sort(rows.begin(), rows.begin() + std::ptrdiff_t(kept), rows.end(), larger);
  rows.resize(kept);
  return rows;
}

FractionSeries::FractionSeries(std::vector<std::uint32_t> polygons, std::int64_t steps,
                               std::int64_t step_seconds, std::size_t points)
    : polygons_(std::move(polygons)) {
  SHADOWKIT_CHECK(points > 0 && step_seconds > 0);
  const auto most = std::int64_t(points);
  steps_per_point_ = std::max<std::int64_t>(1, (steps + most - 1) / most);
  if (steps_per_point_ > 1 && kDay % step_seconds == 0) {
    const std::int64_t steps_per_day = kDay / step_seconds;
    if (steps_per_point_ * 24 > steps_per_day) {
      steps_per_point_ = (steps_per_point_ + steps_per_day - 1) / steps_per_day * steps_per_day;
    }
  }
  const auto n = std::size_t((steps + steps_per_point_ - 1) / steps_per_point_);
  sums_.assign(polygons_.size() * n, 0.0);
  counts_.assign(n, 0);
  sun_up_.assign(n, 0);
  first_.resize(n);
  last_.resize(n);
}

void FractionSeries::add_step(sun::Instant t, bool sun_up, const float* fractions) {
  const auto j = std::size_t(added_++ / steps_per_point_);
  SHADOWKIT_CHECK(j < counts_.size());
  if (counts_[j]++ == 0) first_[j] = t;
  last_[j] = t;
  if (!sun_up) return;
  ++sun_up_[j];
  for (std::size_t line = 0; line < polygons_.size(); ++line) {
    sums_[line * counts_.size() + j] += fractions[polygons_[line]];
  }
}

std::string fraction_plot_svg(const FractionSeries& series, const std::vector<std::string>& labels,
                              double utc_offset_hours) {
  SHADOWKIT_CHECK(labels.size() == series.polygons().size());
  const TimeFrame frame = time_frame(series, utc_offset_hours);
  const std::size_t legend_rows = (labels.size() + 1) / 2;
  const int height = kTop + kPlotHeight + kBelow + int(legend_rows) * kLegendRow + 8;
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " +
                    std::to_string(kWidth) + " " + std::to_string(height) + "\" width=\"" +
                    std::to_string(kWidth) + "\" height=\"" + std::to_string(height) +
                    "\" font-family=\"sans-serif\" font-size=\"12\" role=\"img\">\n"
                    "<title>Sunlit fraction of the largest polygons over the study</title>\n";
  svg += fraction_axis() + time_axis(frame, utc_offset_hours);
  for (std::size_t line = 0; line < labels.size(); ++line) {
    svg += polygon_line(series, frame, line) + legend_entry(labels[line], line);
  }
  return svg + "</svg>\n";
}

}  // namespace shadowkit::sun_study
