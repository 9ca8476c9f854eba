#pragma once
/// \brief The astrometry behind sun_position(), with its time scales and the observer's height
/// given explicitly, so that tests can reproduce the conventions of published SPA results.
#include "shadowkit/scene/sun_position.h"

namespace shadowkit::sun {

/// A Julian date as ERFA takes it: a whole part and a fraction, summed (two parts keep
/// microsecond resolution).
struct JulianDate {
  double whole = 0;
  double fraction = 0;
};

/// The Julian date of an instant's calendar date and clock time, with no leap seconds.
JulianDate julian_date(Instant t);

/// \p date moved by \p seconds.
inline JulianDate plus_seconds(JulianDate date, double seconds) {
  return {date.whole, date.fraction + seconds / 86400.0};
}

/// The two time scales the sun's position depends on: UT1 turns the Earth, TT moves the
/// Earth along its orbit and the equator among the stars.
struct TimeScales {
  JulianDate ut1;
  JulianDate tt;
};

/// UT1 and TT for the contract: UT1 = UTC, and TT = UTC + 32.184 s + (TAI - UTC) from ERFA's
/// table of leap seconds (0 before 1960, the last value after the table ends).
TimeScales contract_time_scales(Instant t);

/// The sun's topocentric azimuth and elevation, without refraction, for an observer
/// \p height_m above the WGS84 ellipsoid at the given geodetic latitude and east longitude.
SunAngles topocentric_sun(double latitude_deg, double longitude_deg, double height_m,
                          const TimeScales& time);

}  // namespace shadowkit::sun
