// The sun's position for sun-study, from ERFA (the IAU SOFA routines, BSD-licensed; Debian's
// liberfa-dev).
//
// Why ERFA: the sun-study contract ("Sun position") asks for the topocentric azimuth and
// elevation of the sun's centre within 0.003 degree of NREL's SPA [Reda & Andreas 2004] for
// 1950-2100. Measured against SPA's own published outputs (the SPA report's worked example,
// and the 384 positions of 1910, 2010 and 2110 in spa_reference_data.h), with SPA's time
// scales and refraction reproduced:
// - ERFA, the chain below: at most 0.00019 degree on the sky and 0.00017 degree in elevation
//   (0.00098 degree in azimuth alone, 9 degrees from the zenith); at the worked example
//   0.00013 degree in azimuth and 0.00003 degree in elevation. SPA states its own uncertainty
//   as 0.0003 degree.
// - libnova 0.16 (libnova-dev), ln_get_solar_equ_coords + ln_get_parallax +
//   ln_get_hrz_from_equ: 0.14 degree in 2010 and 1.7 degree in 1910, since its solar
//   coordinates are not precessed to the date; even with ln_get_equ_prec2 and apparent
//   sidereal time added by hand, 0.0056 degree in 2010 and 0.013 degree in 2110, the error of
//   its truncated VSOP87 series and its nutation.
// So ERFA: its precession-nutation, Earth ephemeris (eraEpv00: within 5 km over 1900-2100) and
// aberration leave SPA's own uncertainty as the limit.
#include "shadowkit/scene/sun_position.h"

#include <erfa.h>
#include <erfam.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "shadowkit/core/error.h"
#include "topocentric.h"

namespace shadowkit::sun {
namespace {

using std::chrono::days;
using std::chrono::floor;
using std::chrono::hh_mm_ss;
using std::chrono::year_month_day;

std::string number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

void check_range(double value, double low, double high, const std::string& where,
                 const char* unit) {
  if (!(value >= low && value <= high)) {  // also refuses NaN
    throw InputError(where, "must be between " + number(low) + " and " + number(high) + " " + unit +
                                ", got " + number(value));
  }
}

// Civil offsets are whole minutes, from UTC-12 to UTC+14, and -14 to 14 hours takes them all;
// a fraction of a minute is a typing error, and whole minutes keep every step on whole seconds.
std::chrono::minutes utc_offset(double hours, const std::string& where) {
  check_range(hours, -14, 14, where, "hours");
  const double minutes = hours * 60;
  const double whole = std::round(minutes);
  // 1e-6 minute absorbs the rounding of decimal hours such as 5.75 or 0.1 in binary.
  if (std::abs(minutes - whole) > 1e-6) {
    throw InputError(where, "must be a whole number of minutes, got " + number(hours) + " hours");
  }
  return std::chrono::minutes{static_cast<int>(whole)};
}

// Reads \p text laid out as \p pattern, where '#' is one decimal digit and any other
// character stands for itself: the fixed-width ISO 8601 forms of the contract, nothing looser.
Instant parse_time(std::string_view text, std::string_view pattern, const std::string& expected,
                   const std::string& where) {
  const auto bad = [&](const std::string& what) {
    return InputError(where + " '" + std::string(text) + "'", what);
  };
  if (text.size() != pattern.size()) throw bad("expected " + expected);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const bool digit = std::isdigit(static_cast<unsigned char>(text[i])) != 0;
    if (pattern[i] == '#' ? !digit : text[i] != pattern[i]) throw bad("expected " + expected);
  }
  const auto field = [&](std::size_t at, std::size_t width) {
    int value = 0;
    for (std::size_t i = at; i < at + width; ++i) value = value * 10 + (text[i] - '0');
    return value;
  };
  const int hour = field(11, 2), minute = field(14, 2);
  const int second = pattern.size() > 16 ? field(17, 2) : 0;
  const year_month_day date{std::chrono::year{field(0, 4)},
                            std::chrono::month{static_cast<unsigned>(field(5, 2))},
                            std::chrono::day{static_cast<unsigned>(field(8, 2))}};
  if (!date.ok()) throw bad("no such date");
  if (hour > 23) throw bad("the hour must be 00 to 23");
  if (minute > 59) throw bad("the minute must be 00 to 59");
  // A leap second has no Instant (sun_position.h).
  if (second > 59) throw bad("the second must be 00 to 59");
  return std::chrono::sys_days{date} + std::chrono::hours{hour} + std::chrono::minutes{minute} +
         std::chrono::seconds{second};
}

}  // namespace

void validate(const Site& site, const SiteFieldNames& names) {
  check_range(site.latitude_deg, -90, 90, names.latitude, "degrees");
  check_range(site.longitude_deg, -180, 180, names.longitude, "degrees");
  utc_offset(site.utc_offset_hours, names.utc_offset);
  check_range(site.north_deg, -360, 360, names.north, "degrees");
}

Instant parse_local_time(std::string_view text, double utc_offset_hours, const std::string& where) {
  const auto offset = utc_offset(utc_offset_hours, "--utc-offset");
  // Local standard time is UTC + offset (the contract's "Command"), so UTC = local - offset.
  return parse_time(text, "####-##-##T##:##", "YYYY-MM-DDTHH:MM (local standard time)", where) -
         offset;
}

Instant parse_utc_time(std::string_view text, const std::string& where) {
  return parse_time(text, "####-##-##T##:##:##Z", "YYYY-MM-DDTHH:MM:SSZ (UTC)", where);
}

std::string format_utc_time(Instant t) {
  const auto day = floor<days>(t);
  const year_month_day date{day};
  const hh_mm_ss clock{t - day};
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02u-%02uT%02d:%02d:%02dZ", static_cast<int>(date.year()),
                static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()),
                static_cast<int>(clock.hours().count()), static_cast<int>(clock.minutes().count()),
                static_cast<int>(clock.seconds().count()));
  return text;
}

JulianDate julian_date(Instant t) {
  const auto day = floor<days>(t);
  // 1970-01-01T00:00 is JD 2440587.5; the whole part stays an exact double.
  return {2440587.5 + static_cast<double>(day.time_since_epoch().count()),
          static_cast<double>((t - day).count()) / 86400.0};
}

TimeScales contract_time_scales(Instant t) {
  const JulianDate utc = julian_date(t);
  const auto day = floor<days>(t);
  const year_month_day date{day};
  double tai_minus_utc = 0;
  // Status 1 ("dubious year") comes before 1960, where UTC did not exist and ERFA gives 0, and
  // a few years past ERFA's table, where it keeps the last value. With UT1 = UTC, TT - UT1 is
  // then the Earth's ΔT within 3.1 s from 1950 to the end of the table, and after that
  // whatever the Earth's rotation does. A reference that assumes a forecast ΔT instead differs by
  // that much time: Espenak & Meeus's forecast for 2100 (203 s, which pvlib uses) is 134 s more
  // than ours, which moves the sun by 0.0016 degree at most (sun_position_test's SPA positions
  // again).
  const int status = eraDat(static_cast<int>(date.year()), static_cast<int>(unsigned{date.month()}),
                            static_cast<int>(unsigned{date.day()}), utc.fraction, &tai_minus_utc);
  if (status < 0) {
    throw InputError(format_utc_time(t), "outside the years whose sun position can be computed");
  }
  // The contract takes UT1 = UTC.
  return {utc, plus_seconds(utc, ERFA_TTMTAI + tai_minus_utc)};
}

SunAngles topocentric_sun(double latitude_deg, double longitude_deg, double height_m,
                          const TimeScales& time) {
  const double tt1 = time.tt.whole, tt2 = time.tt.fraction;
  // Earth orientation, as eraApco13 computes it but from our own TT and UT1: the
  // bias-precession-nutation matrix, its CIP X, Y and CIO locator s; the Earth rotation angle;
  // the TIO locator s'. IAU 2000B nutation (77 terms, within 0.001 arcsecond of the full IAU
  // 2000A series) instead of eraPnm06a (1365 terms): the same sun to 0.000005 degree in a
  // fifteenth of the time, which was half of sun_position()'s. Polar motion (under 0.5
  // arcsecond) is unknown without IERS bulletins and left 0, as SPA does.
  double bpn[3][3];
  eraPnm00b(tt1, tt2, bpn);
  double x = 0, y = 0;
  eraBpn2xy(bpn, &x, &y);
  const double s = eraS00(tt1, tt2, x, y);
  const double era = eraEra00(time.ut1.whole, time.ut1.fraction);
  const double sp = eraSp00(tt1, tt2);
  // The Earth's heliocentric and barycentric position and velocity. TT stands for TDB: they
  // differ by under 2 ms.
  double earth_helio[2][3], earth_bary[2][3];
  eraEpv00(tt1, tt2, earth_helio, earth_bary);
  // Star-independent parameters for a terrestrial observer: eh and em give the observer's
  // (not the geocentre's) direction and distance from the sun, so the topocentric parallax
  // (up to 0.0024 degree) is in them; v is the observer's barycentric velocity, including the
  // Earth's rotation, so diurnal aberration is in the annual step below. Refraction
  // constants 0: no atmosphere, as the contract says.
  eraASTROM astrom;
  eraApco(tt1, tt2, earth_bary, earth_helio[0], x, y, s, era, longitude_deg * ERFA_DD2R,
          latitude_deg * ERFA_DD2R, height_m, 0, 0, sp, 0, 0, &astrom);
  // From the observer to where the sun was when its light left it, 499 s earlier: the sun
  // moves about the barycentre at about 13 m/s, so this term is only 0.000003 degree.
  const double light_days = astrom.em * ERFA_AULT / ERFA_DAYSEC;
  double to_sun[3];
  for (int i = 0; i < 3; ++i) {
    const double sun_velocity = earth_bary[1][i] - earth_helio[1][i];
    to_sun[i] = -astrom.eh[i] * astrom.em - sun_velocity * light_days;
  }
  double natural[3], distance = 0;
  eraPn(to_sun, &distance, natural);
  // Annual aberration (about 20.5 arcseconds, 0.0057 degree). No light deflection: the sun
  // does not bend its own light toward the observer.
  double proper[3], cirs[3];
  eraAb(natural, astrom.v, astrom.em, astrom.bm1, proper);
  eraRxp(astrom.bpn, proper, cirs);
  double ra = 0, dec = 0;
  eraC2s(cirs, &ra, &dec);
  // CIRS to the horizon: Earth rotation and the site's meridian; refraction is 0 above.
  double azimuth = 0, zenith = 0, hour_angle = 0, observed_dec = 0, observed_ra = 0;
  eraAtioq(ra, dec, &astrom, &azimuth, &zenith, &hour_angle, &observed_dec, &observed_ra);
  SunAngles sun{azimuth * ERFA_DR2D, 90.0 - zenith * ERFA_DR2D};
  // eraAtioq gives 0 <= azimuth < 2 pi; degrees may round up to 360.
  if (sun.azimuth_deg >= 360.0) sun.azimuth_deg -= 360.0;
  return sun;
}

SunAngles sun_position(const Site& site, Instant t) {
  validate(site);
  // At sea level, as the contract says: the observer's height above the ellipsoid.
  return topocentric_sun(site.latitude_deg, site.longitude_deg, 0.0, contract_time_scales(t));
}

Vec3 toward_sun(const SunAngles& sun, double north_deg) {
  const double n = north_deg * ERFA_DD2R;
  // North turned clockwise seen from above (from +Y) by N; east is north turned a further
  // 90 degrees clockwise, so that east x north = up and N = 0 gives north -Z, east +X.
  const Vec3 north{std::sin(n), 0, -std::cos(n)};
  const Vec3 east{std::cos(n), 0, std::sin(n)};
  const Vec3 up{0, 1, 0};
  const double a = sun.azimuth_deg * ERFA_DD2R, e = sun.elevation_deg * ERFA_DD2R;
  return std::cos(e) * (std::sin(a) * east + std::cos(a) * north) + std::sin(e) * up;
}

}  // namespace shadowkit::sun
