#pragma once

// How messages name an hour of a weather file: "month 3 day 21 hour 13".

#include <string>

#include "shadowgen/model/scene.h"

namespace shadowgen::weather::detail {

inline std::string hour_text(int month, int day, int hour) {
  return "month " + std::to_string(month) + " day " + std::to_string(day) + " hour " +
         std::to_string(hour);
}

inline std::string hour_text(const WeatherHour& hour) {
  return hour_text(hour.month, hour.day, hour.hour);
}

}  // namespace shadowgen::weather::detail
