// Locale-independent number text for files: the mechanism format, motion tables and the command
// line must read the same in every locale, so nothing here goes through printf, strtod or streams.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace linkage {

// The value rounded to `significant` (clamped to 1..17) significant digits in general format, as
// printf's %.*g would write it in the C locale: trailing zeros dropped, exponent form only for very
// large or small magnitudes ("0.10000000000000001", "1e-07", "123456", "2.5e+20"). 17 digits
// round-trip every double. '.' as decimal point; negative zero is written as "0".
// A non-finite value is a caller bug: it asserts; with NDEBUG it returns "" (an empty field) rather
// than "nan" or "inf", which no reader of our files accepts.
std::string formatNumber(double v, int significant = 17);

// A number for people to read (notes, `info`; not the tables, which keep 17 digits): rounded to
// `significant` digits, and 0 when it is rounding next to `scale` (at most 1e-9 of it: the
// solver's results agree with closed forms to about 1e-12 of their peak, so -8.8e-17 next to
// 0.5 is an exact zero).
std::string formatShown(double v, double scale = 0, int significant = 6);

// The whole of `text` must be one finite number in decimal or scientific notation ("1.5", "-2e3",
// an optional leading '+'). No whitespace, no "inf"/"nan", no hex; out-of-range values (1e999, and
// underflow such as 1e-400) are refused. Independent of the global locale.
std::optional<double> parseNumber(std::string_view text);

}  // namespace linkage
