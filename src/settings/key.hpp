#pragma once
// One setting, declared once with its name, unit, help, rule (a range or a list of choices) and the
// member it sets; the default is the member's initialiser. From the declaration come the parser
// (text to value, checked), the writer (value to text that reads back bit for bit), the --help line
// and the check of a value set in code, so the rule cannot differ between them.

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "settings/value_text.hpp"

namespace fragsim::settings {

// An interval rule, [lo, hi] with either end open.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const;  // "must be in (0, 180)", "must be >= 0"
};

inline Range closed(double lo, double hi) {
  return {lo, hi, false, false};
}
inline Range open_closed(double lo, double hi) {
  return {lo, hi, true, false};
}
inline Range open(double lo, double hi) {
  return {lo, hi, true, true};
}

// One setting of an `Owner` struct.
template <class Owner>
struct Key {
  std::string name;  // "key" in its struct; "section.key" once placed in a section
  std::string help;  // "choices; unit; meaning", as --help prints it
  // Text to value; throws ValueError naming the rule.
  std::function<void(Owner&, const std::string&)> parse;
  // Value to text that parses back as the same value.
  std::function<std::string(const Owner&)> format;
  // The rule the value held breaks (a value set in code), or nothing.
  std::function<std::optional<std::string>(const Owner&)> broken;
};

template <class Owner>
using Keys = std::vector<Key<Owner>>;

// The help line, with the non-empty parts joined by "; ".
std::string help_text(std::initializer_list<std::string_view> parts);

// The rules, shared by parsing and by checking a value set in code.
std::optional<std::string> real_rule(double v, const Range& range);
std::optional<std::string> real_or_inf_rule(double v, const Range& range);
std::optional<std::string> integer_rule(long long v, long long lo, long long hi);
std::optional<std::string> vec3_rule(const Eigen::Vector3d& v, const Range& each);

// A number in `range`.
template <class Owner>
Key<Owner> real(std::string name, std::string_view unit, std::string_view help, double Owner::*m,
                Range range) {
  return {std::move(name), help_text({unit, help}),
          [m, range](Owner& o, const std::string& text) {
            const double v = parse_double(text);
            if (auto rule = real_rule(v, range)) throw ValueError{*rule};
            o.*m = v;
          },
          [m](const Owner& o) { return format_double(o.*m); },
          [m, range](const Owner& o) { return real_rule(o.*m, range); }};
}

// A duration or rate for which `inf` means "never" or "at once"; every other value is finite.
template <class Owner>
Key<Owner> real_or_inf(std::string name, std::string_view unit, std::string_view help,
                       double Owner::*m, Range range) {
  return {std::move(name), help_text({unit, help}),
          [m, range](Owner& o, const std::string& text) {
            const double v = parse_double_or_inf(text);
            if (auto rule = real_or_inf_rule(v, range)) throw ValueError{*rule};
            o.*m = v;
          },
          [m](const Owner& o) {
            return o.*m == std::numeric_limits<double>::infinity() ? std::string("inf")
                                                                   : format_double(o.*m);
          },
          [m, range](const Owner& o) { return real_or_inf_rule(o.*m, range); }};
}

// A whole number in [lo, hi].
template <class Owner, class Int>
Key<Owner> integer(std::string name, std::string_view unit, std::string_view help, Int Owner::*m,
                   long long lo, long long hi) {
  return {std::move(name), help_text({unit, help}),
          [m, lo, hi](Owner& o, const std::string& text) {
            const long long v = parse_integer(text);
            if (auto rule = integer_rule(v, lo, hi)) throw ValueError{*rule};
            o.*m = static_cast<Int>(v);
          },
          [m](const Owner& o) { return std::to_string(o.*m); },
          [m, lo, hi](const Owner& o) { return integer_rule(o.*m, lo, hi); }};
}

// on | off (also true/false, yes/no, 1/0 when read).
template <class Owner>
Key<Owner> boolean(std::string name, std::string_view help, bool Owner::*m) {
  return {std::move(name), help_text({"on|off", help}),
          [m](Owner& o, const std::string& text) {
            const std::string v = trim(text);
            if (v == "on" || v == "true" || v == "yes" || v == "1") {
              o.*m = true;
            } else if (v == "off" || v == "false" || v == "no" || v == "0") {
              o.*m = false;
            } else {
              throw ValueError{"expected on or off"};
            }
          },
          [m](const Owner& o) { return std::string(o.*m ? "on" : "off"); },
          [](const Owner&) { return std::optional<std::string>(); }};
}

// One of named values; the help line starts with the names.
template <class Owner, class Enum>
Key<Owner> choice(std::string name, std::string_view help, Enum Owner::*m,
                  std::vector<std::pair<std::string, Enum>> names) {
  std::string known;
  for (const auto& [n, e] : names) known += (known.empty() ? "" : " | ") + n;
  const std::string rule = "expected " + known;
  return {std::move(name), help_text({known, help}),
          [m, names, rule](Owner& o, const std::string& text) {
            const std::string v = trim(text);
            for (const auto& [n, e] : names) {
              if (n == v) {
                o.*m = e;
                return;
              }
            }
            throw ValueError{rule};
          },
          [m, names](const Owner& o) {
            for (const auto& [n, e] : names) {
              if (o.*m == e) return n;
            }
            return std::string("?");
          },
          [m, names, rule](const Owner& o) {
            for (const auto& [n, e] : names) {
              if (o.*m == e) return std::optional<std::string>();
            }
            return std::optional<std::string>(rule);
          }};
}

// Three numbers 'x y z', each in `each`.
template <class Owner>
Key<Owner> vec3(std::string name, std::string_view unit, std::string_view help,
                Eigen::Vector3d Owner::*m, Range each) {
  return {std::move(name), help_text({unit, help}),
          [m, each](Owner& o, const std::string& text) {
            const Eigen::Vector3d v = parse_vec3(text);
            if (auto rule = vec3_rule(v, each)) throw ValueError{*rule};
            o.*m = v;
          },
          [m](const Owner& o) { return format_vec3(o.*m); },
          [m, each](const Owner& o) { return vec3_rule(o.*m, each); }};
}

// A list of points 'x y z; x y z; ...', at least one and at most 1000, each component in
// [-1e6, 1e6].
template <class Owner>
Key<Owner> points(std::string name, std::string_view unit, std::string_view help,
                  std::vector<Eigen::Vector3d> Owner::*m) {
  return {std::move(name), help_text({unit, help}),
          [m](Owner& o, const std::string& text) { o.*m = parse_points(text); },
          [m](const Owner& o) { return format_points(o.*m); },
          [m](const Owner& o) { return points_rule(o.*m); }};
}

// A plain text value (a file name, a strategy name) of one line with no quotes or commas, so it
// survives config.ini and CSV cells.
template <class Owner>
Key<Owner> text(std::string name, std::string_view help, std::string Owner::*m) {
  return {std::move(name), help_text({help}),
          [m](Owner& o, const std::string& v) {
            const std::string t = trim(v);
            if (auto rule = text_rule(t)) throw ValueError{*rule};
            o.*m = t;
          },
          [m](const Owner& o) { return o.*m; }, [m](const Owner& o) { return text_rule(o.*m); }};
}

// `keys` of the `Inner` struct that `get` finds in an `Outer` one, named "section.key" (just "key"
// for an empty section). `get` is called with an Outer& and a const Outer&.
template <class Outer, class Inner, class Get>
Keys<Outer> in_section(std::string_view section, const Keys<Inner>& keys, Get get) {
  Keys<Outer> out;
  for (const Key<Inner>& k : keys) {
    out.push_back({section.empty() ? k.name : std::string(section) + "." + k.name, k.help,
                   [get, parse = k.parse](Outer& o, const std::string& t) { parse(get(o), t); },
                   [get, format = k.format](const Outer& o) { return format(get(o)); },
                   [get, broken = k.broken](const Outer& o) { return broken(get(o)); }});
  }
  return out;
}

// The one-line messages for a text from `where` (file:line, --option) that breaks the key's rule,
// and for a value set in code that does.
std::string bad_text_message(const std::string& where, const std::string& key,
                             const std::string& text, const std::string& rule);
std::string bad_value_message(const std::string& key, const std::string& value,
                              const std::string& rule);

// Sets `key` from `text`. Throws Error (an InputError) with the message above.
template <class Error = InputError, class Owner>
void apply(const Key<Owner>& key, Owner& owner, const std::string& text, const std::string& where) {
  try {
    key.parse(owner, text);
  } catch (const ValueError& e) {
    throw Error(bad_text_message(where, key.name, trim(text), e.rule));
  }
}

// Checks every value held against its key's rule. Throws Error naming the first key broken.
template <class Error = InputError, class Owner>
void check(const Keys<Owner>& keys, const Owner& owner) {
  for (const Key<Owner>& k : keys) {
    if (auto rule = k.broken(owner)) throw Error(bad_value_message(k.name, k.format(owner), *rule));
  }
}

}  // namespace fragsim::settings
