// SPDX-License-Identifier: Apache-2.0
#pragma once
// Numbers as text, both ways, for files and messages: the shortest decimal that reads back to the
// same double (a message names the value given, not a rounding of it), and a strict reader of
// decimal numbers (no hex, no inf or nan, Fortran 'D' exponents accepted).
#include <string>

namespace blockdyn {

// The shortest decimal text that reads back to exactly v ("0.1", "1e-200", "-5", "inf", "nan").
std::string number_text(double v);
// A computed quantity for a message, to `digits` significant digits ("58.05", "1.2e-05").
std::string number_text(double v, int digits);
// The same in scientific notation with an upper-case exponent ("1.5E-03"), for fixed-width files.
std::string scientific_text(double v);

// Parses a whole token as a decimal number: [+-] digits [. digits] [(E|e|D|d) [+-] digits]. Hex,
// inf, nan, empty or trailing characters are refused (false); so is a value beyond the largest
// double. Underflow reads as the nearest double (a subnormal, or zero).
bool parse_decimal(const std::string& token, double& value);

}  // namespace blockdyn
