#pragma once

// A weather file's hourly direct normal radiation at an instant (docs/scene-format.md,
// "Weather file"), for irradiation outputs.
//
// Timing: EnergyPlus's hour h (1 to 24) holds what was received over the hour ending at
// h:00 local standard time, from (h - 1):00 to h:00. An instant at local standard time
// HH:MM:SS on a day uses that day's hour HH + 1, the hour that starts at or before it and
// ends after it: an instant at exactly h:00 uses the hour that begins there (h + 1, or
// hour 1 of the day at 00:00), never the one that ends there. So an instant and the
// step_min minutes that follow it, as a sun path's instant stands for them, lie in one
// weather hour whenever step_min divides 60, and no instant needs the day before.
// The year is not matched (a typical-year file mixes years): 2026-03-21T12:30 and
// 2031-03-21T12:30 both use month 3, day 21, hour 13.

#include "shadowgen/model/scene.h"
#include "shadowgen/sun/civil_time.h"

namespace shadowgen::weather {

// The hour of `weather` that holds `local_standard_time`; nullptr when the file has none
// (a file of part of a year, or February 29 in a file without it). O(log hours).
const WeatherHour* weather_hour_at(const Weather& weather,
                                   const sun::CivilTime& local_standard_time);

// The hour of `weather` that holds `local_standard_time`; InputError naming the weather
// file when the file has none.
const WeatherHour& weather_hour_needed(const Weather& weather,
                                       const sun::CivilTime& local_standard_time);

// Which radiation of a weather hour an output needs.
enum class Radiation { kGlobalHorizontal, kDirectNormal, kDiffuseHorizontal };

// That radiation of the hour holding `local_standard_time`, in Wh/m2: also the hour's mean
// irradiance in W/m2. InputError naming the weather file when the file has no such hour,
// or (with its line) when it marks the hour's value missing.
double radiation_wh_m2(const Weather& weather, const sun::CivilTime& local_standard_time,
                       Radiation which);

// radiation_wh_m2 of the direct normal radiation.
double direct_normal_wh_m2(const Weather& weather, const sun::CivilTime& local_standard_time);

}  // namespace shadowgen::weather
