#pragma once
// Numbers as text, the one place that decides how. The terminal, the HTML page and every CSV file
// format through these, so one value reads the same wherever it is shown. All use std::to_chars
// (no locale, the same text on every platform).

#include <string>

namespace fragsim {

// The shortest form that reads back as the same double, so scene files round-trip and CSV files
// are byte-for-byte repeatable.
void append_double(std::string& out, double v);
std::string format_double(double v);

// `decimals` digits after the point, rounded from the double's exact value with ties to even (what
// printf's "%.*f" prints). A negative that rounds to zero prints without a sign (never "-0.0"), so
// a solver's -1e-17 reads as the 0 it stands for. NaN prints "nan" (whatever its sign bit),
// infinities "inf" and "-inf".
std::string fixed_text(double v, int decimals);

// A share (0.25) as a percentage with `decimals` digits ("25.0"), rounded as fixed_text.
std::string percent_text(double share, int decimals);

}  // namespace fragsim
