#pragma once

// Fields of the CSV files shadowgen writes (the report, the sun's instants), written one
// way in all of them.

#include <string>
#include <string_view>

#include "shadowgen/output/report.h"

namespace shadowgen::output::detail {

// %.17g, but independent of the C locale's decimal point.
void append_csv_number(std::string& out, double value);

// RFC 4180: a field holding a comma, a quote, CR or LF is quoted, its quotes doubled.
// CsvIds::kSpreadsheetSafe first puts "'" before a field a spreadsheet would take for a
// formula.
void append_csv_field(std::string& out, std::string_view field, CsvIds ids);

}  // namespace shadowgen::output::detail
