#include "shadowgen/model/site_ranges.h"

namespace shadowgen {
namespace {

NumberRange between(double low, double high, const char* unit) {
  NumberRange range;
  range.low = low;
  range.high = high;
  range.unit = unit;
  return range;
}

}  // namespace

NumberRange latitude_range() { return between(-90.0, 90.0, " degrees"); }
NumberRange longitude_range() { return between(-180.0, 180.0, " degrees"); }
NumberRange utc_offset_range() { return between(-14.0, 14.0, " hours"); }
NumberRange elevation_range() { return between(-6'500'000.0, 11'000.0, " m"); }
NumberRange north_axis_range() { return between(-360.0, 360.0, " degrees"); }

}  // namespace shadowgen
