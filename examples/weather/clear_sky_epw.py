#!/usr/bin/env python3
"""Writes a synthetic EnergyPlus weather file (EPW) of cloudless hours for a site.

This is not measured weather: every hour of the year is clear sky by a stated model,
made for the examples (the garden's radiation map) so that no real weather file need be
copied into the project.

Model (Duffie and Beckman, "Solar Engineering of Thermal Processes", 4th ed., 2013):
- extraterrestrial normal irradiance G_on = 1367 (1 + 0.033 cos(360 n / 365)) W/m2, n the
  day of the year (eq. 1.4.1a);
- the sun's zenith angle at the middle of each hour (an EPW row holds the hour that ends
  at its hour field) from Cooper's declination (eq. 1.6.1a) and Spencer's equation of
  time (eq. 1.5.3), in local standard time at the site's longitude and time zone;
- Hottel's clear-sky beam transmittance (1976; eq. 2.8.1): tau_b = a0 + a1 exp(-k /
  cos(zenith)), with a0, a1, k for the 23 km visibility standard atmosphere at the site's
  altitude and the mid-latitude summer corrections (r0 = 0.97, r1 = 0.99, rk = 1.02) all
  year;
- Liu and Jordan's diffuse transmittance (1960; eq. 2.8.5): tau_d = 0.271 - 0.294 tau_b;
- direct normal = G_on tau_b, diffuse horizontal = G_on cos(zenith) tau_d, global
  horizontal = direct normal cos(zenith) + diffuse horizontal, each in Wh/m2 over the
  hour (the irradiance at the hour's middle times one hour), rounded to whole numbers
  as EPW files hold them; 0 where the sun is below the horizon at the hour's middle.
The albedo (field 33) is 0.2 every hour; the other weather fields are fixed, plausible
values (10 C, 80 % humidity, calm), which shadowgen does not read.

  examples/weather/clear_sky_epw.py [--latitude 51.4779 --longitude -0.0015
      --elevation 45 --time-zone 0 --city Greenwich --year 2026] [--output FILE.epw]

(without --output, to standard output). The defaults are the garden example's site
(examples/scenes/garden.json): the build writes its output with them to
BUILD/examples/weather/greenwich-clear-sky.epw (the target example_weather,
examples/CMakeLists.txt), the weather of the garden's radiation map, so that no file of
a year's hours is kept in the repository.
"""

import argparse
import math
import os
import sys

DAYS_IN_MONTH = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
SOLAR_CONSTANT = 1367.0  # W/m2


def cos_zenith(latitude, longitude, time_zone, day_of_year, standard_hour):
    """The cosine of the sun's zenith angle at `standard_hour` (local standard time)."""
    declination = math.radians(23.45 * math.sin(math.radians(360.0 * (284 + day_of_year) / 365.0)))
    b = math.radians((day_of_year - 1) * 360.0 / 365.0)
    equation_of_time_min = 229.2 * (0.000075 + 0.001868 * math.cos(b) - 0.032077 * math.sin(b)
                                    - 0.014615 * math.cos(2 * b) - 0.04089 * math.sin(2 * b))
    solar_hour = standard_hour + (4.0 * (longitude - 15.0 * time_zone) + equation_of_time_min) / 60.0
    hour_angle = math.radians(15.0 * (solar_hour - 12.0))
    phi = math.radians(latitude)
    return (math.cos(phi) * math.cos(declination) * math.cos(hour_angle)
            + math.sin(phi) * math.sin(declination))


def clear_sky(altitude_km, day_of_year, cos_z):
    """(global horizontal, direct normal, diffuse horizontal) in W/m2 under Hottel's sky."""
    if cos_z <= 0.0:
        return 0.0, 0.0, 0.0
    a0 = 0.97 * (0.4237 - 0.00821 * (6.0 - altitude_km) ** 2)
    a1 = 0.99 * (0.5055 + 0.00595 * (6.5 - altitude_km) ** 2)
    k = 1.02 * (0.2711 + 0.01858 * (2.5 - altitude_km) ** 2)
    tau_b = a0 + a1 * math.exp(-k / cos_z)
    tau_d = 0.271 - 0.294 * tau_b
    g_on = SOLAR_CONSTANT * (1.0 + 0.033 * math.cos(math.radians(360.0 * day_of_year / 365.0)))
    direct_normal = g_on * tau_b
    diffuse_horizontal = g_on * cos_z * tau_d
    return direct_normal * cos_z + diffuse_horizontal, direct_normal, diffuse_horizontal


def epw_lines(args):
    yield (f"LOCATION,{args.city},,,Synthetic clear sky (Hottel),000000,{args.latitude},"
           f"{args.longitude},{args.time_zone:.1f},{args.elevation:.1f}")
    yield "DESIGN CONDITIONS,0"
    yield "TYPICAL/EXTREME PERIODS,0"
    yield "GROUND TEMPERATURES,0"
    yield "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0"
    yield ("COMMENTS 1,Synthetic: every hour clear sky by Hottel's beam and Liu and Jordan's "
           "diffuse transmittance; not measured weather")
    yield "COMMENTS 2,Written by shadowgen's examples/weather/clear_sky_epw.py"
    yield "DATA PERIODS,1,1,Data,Thursday, 1/ 1,12/31"
    day_of_year = 0
    for month, days in enumerate(DAYS_IN_MONTH, start=1):
        for day in range(1, days + 1):
            day_of_year += 1
            for hour in range(1, 25):
                cos_z = cos_zenith(args.latitude, args.longitude, args.time_zone, day_of_year,
                                   hour - 0.5)
                ghi, dni, dhi = (round(v) for v in
                                 clear_sky(args.elevation / 1000.0, day_of_year, cos_z))
                yield (f"{args.year},{month},{day},{hour},60,"
                       "?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9?9?9,"
                       f"10.0,6.6,80,101325,0,0,300,{ghi},{dni},{dhi},"
                       "999999,999999,999999,9999,0,0.0,0,0,9999,77777,9,999999999,0,0.0,0,88,"
                       "0.200,0.0,0.0")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--latitude", type=float, default=51.4779)
    parser.add_argument("--longitude", type=float, default=-0.0015)
    parser.add_argument("--elevation", type=float, default=45.0, help="metres")
    parser.add_argument("--time-zone", type=float, default=0.0, help="hours from GMT")
    parser.add_argument("--city", default="Greenwich")
    parser.add_argument("--year", type=int, default=2026)
    parser.add_argument("--output", help="the file to write (default: standard output)")
    args = parser.parse_args()
    text = "".join(line + "\n" for line in epw_lines(args))
    if args.output is None:
        sys.stdout.write(text)
        return
    # Written beside the file and renamed over it: a build stopped midway leaves no
    # half-written file that make would take for up to date.
    partial = args.output + ".partial"
    with open(partial, "w", encoding="ascii", newline="\n") as out:
        out.write(text)
    os.replace(partial, args.output)


if __name__ == "__main__":
    main()
