#pragma once
/// \brief Where the sun is, seen from a site on the Earth, and which way that is in a scene:
/// the "Sun position" and "Orientation" sections of the sun-study contract
/// (sun-study.md), with the times its options and outputs are written in.
#include <chrono>
#include <string>
#include <string_view>

#include "shadowkit/core/vec.h"

namespace shadowkit::sun {

/// An instant in UTC: whole seconds since 1970-01-01T00:00:00Z on the proleptic Gregorian
/// calendar, every day 86400 seconds long (POSIX time, what std::chrono::system_clock
/// counts). A leap second (23:59:60) has no instant of its own; the sun moves 0.004 degree
/// in one second, so nothing the contract measures needs it.
using Instant = std::chrono::sys_seconds;

/// \brief Where the study stands and how its scene is turned. Each field is one option of
/// `sun-study`, which validate() names when the value is out of range.
struct Site {
  double latitude_deg = 0;      ///< `--lat`: geodetic, north positive, -90 to 90
  double longitude_deg = 0;     ///< `--lon`: east positive, -180 to 180
  double utc_offset_hours = 0;  ///< `--utc-offset`: local standard time is UTC + this, -14 to 14
                                ///< hours in whole minutes (every civil offset is)
  double north_deg = 0;         ///< `--north`: north turned clockwise, seen from above, from -Z;
                                ///< -360 to 360
};

/// \brief What validate() calls each field of a Site in its messages: the options of
/// `sun-study`, or where else the values came from (a scene file's `site` keys).
struct SiteFieldNames {
  std::string latitude = "--lat";
  std::string longitude = "--lon";
  std::string utc_offset = "--utc-offset";
  std::string north = "--north";
};

/// Throws InputError naming (\p names) the first field that is out of range or not a number.
void validate(const Site& site, const SiteFieldNames& names = {});

/// Reads `YYYY-MM-DDTHH:MM` as local standard time, UTC + \p utc_offset_hours (no daylight
/// saving: the contract's `--from` and `--to`). A date that does not exist (2025-02-30), an
/// hour or minute out of range or any other text throws InputError at \p where (the option's
/// name, e.g. "--from"); so does an offset that validate() would refuse, at `--utc-offset`.
Instant parse_local_time(std::string_view text, double utc_offset_hours, const std::string& where);

/// Reads `YYYY-MM-DDTHH:MM:SSZ`, the form of `times.csv`'s `time_utc`; errors as above.
Instant parse_utc_time(std::string_view text, const std::string& where);

/// Writes `YYYY-MM-DDTHH:MM:SSZ` (`times.csv`'s `time_utc`); parse_utc_time() reads it back.
std::string format_utc_time(Instant t);

/// \brief The direction of the sun's centre in the site's horizon.
struct SunAngles {
  double azimuth_deg = 0;    ///< clockwise from north, seen from above: 0 <= azimuth < 360
  double elevation_deg = 0;  ///< above the horizon, -90 to 90
};

/// The topocentric azimuth and elevation of the sun's centre at \p t, without atmospheric
/// refraction, for an observer at sea level (on the WGS84 ellipsoid) at the site, taking
/// UT1 = UTC: the contract's "Sun position". Within 0.0002 degree of NREL's SPA (Reda & Andreas
/// 2004) for 1910-2110 given the same time scales (sun_position_test); the contract asks for
/// 0.003 degree for 1950-2100. Other years are computed with the same models, less accurately
/// the further they are from 2000. Throws InputError for an invalid site (validate()).
/// About 40 microseconds a call; thread-safe (it keeps no state), so steps may run in parallel.
SunAngles sun_position(const Site& site, Instant t);

/// The unit vector toward the sun in scene coordinates (+Y up; north -Z and east +X when
/// \p north_deg is 0; north = (sin N, 0, -cos N) and east = (cos N, 0, sin N) for
/// N = \p north_deg): cos E (sin A east + cos A north) + sin E up, the contract's
/// "Orientation". A directional light shines the opposite way.
Vec3 toward_sun(const SunAngles& sun, double north_deg);

}  // namespace shadowkit::sun
