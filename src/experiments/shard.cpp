#include "experiments/shard.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <map>
#include <optional>

#include "io/input_file.hpp"
#include "io/visible_text.hpp"

namespace fragsim {
namespace {

constexpr const char* kSlicePrefix = "# fragsim slice: ";

std::optional<std::size_t> whole_number(const std::string& s) {
  if (s.empty() || s.size() > 18) return std::nullopt;  // 18 digits cannot overflow 64 bits
  std::size_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + static_cast<std::size_t>(c - '0');
  }
  return v;
}

std::size_t count_lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

std::string shard_text(const Shard& s) {
  return std::to_string(s.index) + "/" + std::to_string(s.count);
}

// "A-B/M" into a range and M.
bool parse_jobs(const std::string& text, JobRange& range, std::size_t& total) {
  const auto dash = text.find('-');
  const auto slash = text.find('/');
  if (dash == std::string::npos || slash == std::string::npos || slash < dash) return false;
  const auto b = whole_number(text.substr(0, dash));
  const auto e = whole_number(text.substr(dash + 1, slash - dash - 1));
  const auto m = whole_number(text.substr(slash + 1));
  if (!b || !e || !m) return false;
  range = {*b, *e};
  total = *m;
  return true;
}

// The slice line's fields, in their fixed order. Throws ShardError naming file:1.
SliceHeader parse_slice_line(const std::string& line, const std::string& name) {
  const auto bad = [&](const std::string& why) { throw ShardError(name + ":1: " + why); };
  if (line.rfind(kSlicePrefix, 0) != 0) {
    bad(std::string("not a slice (no '") + kSlicePrefix +
        "...' line: was it written with --shard?)");
  }
  const std::string rest = line.substr(std::string(kSlicePrefix).size());
  std::vector<std::string> words;
  std::size_t at = 0;
  while (at <= rest.size()) {
    const std::size_t sp = rest.find(' ', at);
    words.push_back(rest.substr(at, sp == std::string::npos ? std::string::npos : sp - at));
    if (sp == std::string::npos) break;
    at = sp + 1;
  }
  const char* keys[] = {"command=", "shard=", "plan=", "jobs=", "rows="};
  if (words.size() != 5) bad("malformed slice line (expected command= shard= plan= jobs= rows=)");
  std::string value[5];
  for (int i = 0; i < 5; ++i) {
    if (words[static_cast<std::size_t>(i)].rfind(keys[i], 0) != 0) {
      bad(std::string("malformed slice line (expected ") + keys[i] + "...)");
    }
    value[i] = words[static_cast<std::size_t>(i)].substr(std::string(keys[i]).size());
  }
  SliceHeader h;
  h.command = value[0];
  if (h.command != "sweep" && h.command != "suite")
    bad("unknown command '" + visible_text(h.command) + "'");
  try {
    h.shard = parse_shard(value[1]);
  } catch (const ShardError& e) {
    bad(std::string("shard=") + e.what());
  }
  h.plan = value[2];
  if (h.plan.size() != 16 || h.plan.find_first_not_of("0123456789abcdef") != std::string::npos) {
    bad("plan='" + visible_text(h.plan) + "' is not 16 hex digits");
  }
  if (!parse_jobs(value[3], h.range, h.total_jobs))
    bad("jobs='" + visible_text(value[3]) + "' is not B-E/M");
  const auto rows = whole_number(value[4]);
  if (!rows) bad("rows='" + visible_text(value[4]) + "' is not a whole number");
  h.rows = *rows;
  const JobRange expected = shard_range(h.total_jobs, h.shard);
  if (h.range.begin != expected.begin || h.range.end != expected.end) {
    bad("jobs=" + value[3] + " is not slice " + shard_text(h.shard) + " of " +
        std::to_string(h.total_jobs) + " jobs (" + std::to_string(expected.begin) + "-" +
        std::to_string(expected.end) + ")");
  }
  return h;
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto k = slash == std::string::npos ? std::nullopt : whole_number(text.substr(0, slash));
  const auto n = slash == std::string::npos ? std::nullopt : whole_number(text.substr(slash + 1));
  if (!k || !n)
    throw ShardError("'" + visible_text(text) + "': expected K/N, whole numbers, e.g. 0/4");
  if (*n < 1 || *n > kMaxShards) {
    throw ShardError("'" + visible_text(text) + "': N must be 1.." + std::to_string(kMaxShards));
  }
  if (*k >= *n) {
    throw ShardError("'" + visible_text(text) + "': K counts from 0 and must be below N (0/" +
                     std::to_string(*n) + " .. " + std::to_string(*n - 1) + "/" +
                     std::to_string(*n) + ")");
  }
  return {*k, *n};
}

JobRange shard_range(std::size_t jobs, const Shard& shard) {
  // floor(jobs k / N) without the product. jobs = q N + r gives q k + floor(r k / N), and
  // r k < N^2 <= 1e12 fits 64 bits whatever the number of jobs.
  const std::size_t q = jobs / shard.count, r = jobs % shard.count;
  const auto at = [&](std::size_t k) { return q * k + r * k / shard.count; };
  return {at(shard.index), at(shard.index + 1)};
}

std::string plan_fingerprint(const std::string& plan_text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : plan_text) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

PlanText& PlanText::add(const std::string& part) {
  text_ += std::to_string(part.size());
  text_ += ':';
  text_ += part;
  text_ += '\n';
  return *this;
}

std::string slice_line(const std::string& command, const Shard& shard, const std::string& plan,
                       std::size_t total_jobs, const std::string& csv) {
  const JobRange r = shard_range(total_jobs, shard);
  const std::size_t lines = count_lines(csv);
  return std::string(kSlicePrefix) + "command=" + command + " shard=" + shard_text(shard) +
         " plan=" + plan + " jobs=" + std::to_string(r.begin) + "-" + std::to_string(r.end) + "/" +
         std::to_string(total_jobs) + " rows=" + std::to_string(lines > 0 ? lines - 1 : 0) + "\n";
}

std::string merge_slices(const std::vector<SliceFile>& files, std::string* command) {
  if (files.empty()) throw ShardError("no slice files given");
  struct Slice {
    const SliceFile* file;
    SliceHeader header;
    std::string columns;  // the CSV header line, with its '\n'
    std::string rows;     // everything after it
  };
  std::vector<Slice> slices;
  // A slice saved on Windows (or through an editor that writes "\r\n") is the same slice.
  std::vector<SliceFile> unix_files;
  for (const SliceFile& f : files)
    unix_files.push_back({f.name, without_carriage_returns(f.bytes)});
  for (const SliceFile& f : unix_files) {
    const auto eol = f.bytes.find('\n');
    if (eol == std::string::npos) {
      parse_slice_line(f.bytes, f.name);  // names what is wrong with the only line
      throw ShardError(f.name + ":2: no CSV header after the slice line");
    }
    Slice s{&f, parse_slice_line(f.bytes.substr(0, eol), f.name), {}, {}};
    const auto eol2 = f.bytes.find('\n', eol + 1);
    if (eol2 == std::string::npos) throw ShardError(f.name + ":2: no CSV header line");
    s.columns = f.bytes.substr(eol + 1, eol2 - eol);
    s.rows = f.bytes.substr(eol2 + 1);
    if (!s.rows.empty() && s.rows.back() != '\n') {
      throw ShardError(f.name + ": the last row has no line end (a cut file?)");
    }
    const std::size_t rows = count_lines(s.rows);
    if (rows != s.header.rows) {
      throw ShardError(f.name + ": " + std::to_string(rows) + " rows, its slice line says " +
                       std::to_string(s.header.rows) + " (a cut or edited file?)");
    }
    slices.push_back(std::move(s));
  }

  const Slice& first = slices.front();
  std::map<std::size_t, const Slice*> by_index;
  for (const Slice& s : slices) {
    const SliceHeader& h = s.header;
    const std::string& name = s.file->name;
    if (h.command != first.header.command) {
      throw ShardError(name + ": a " + h.command + " slice; " + first.file->name + " is a " +
                       first.header.command + " slice");
    }
    if (h.plan != first.header.plan || h.total_jobs != first.header.total_jobs) {
      throw ShardError(name + ": a slice of another plan (plan " + h.plan + ", " +
                       std::to_string(h.total_jobs) + " jobs; " + first.file->name + ": plan " +
                       first.header.plan + ", " + std::to_string(first.header.total_jobs) +
                       " jobs)");
    }
    if (h.shard.count != first.header.shard.count) {
      throw ShardError(name + ": slice " + shard_text(h.shard) + " of a split into " +
                       std::to_string(h.shard.count) + "; " + first.file->name + " is slice " +
                       shard_text(first.header.shard) + " of a split into " +
                       std::to_string(first.header.shard.count));
    }
    if (s.columns != first.columns) {
      throw ShardError(name + ":2: the CSV header differs from " + first.file->name + "'s");
    }
    const auto [it, fresh] = by_index.emplace(h.shard.index, &s);
    if (!fresh) {
      throw ShardError(name + ": slice " + shard_text(h.shard) + " is given twice (also " +
                       it->second->file->name + ")");
    }
  }
  const std::size_t n = first.header.shard.count;
  if (by_index.size() != n) {
    std::string missing;
    std::size_t listed = 0, absent = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (by_index.count(k)) continue;
      ++absent;
      if (listed < 8) {
        missing += (listed ? ", " : "") + std::to_string(k) + "/" + std::to_string(n);
        ++listed;
      }
    }
    if (absent > listed) missing += " and " + std::to_string(absent - listed) + " more";
    throw ShardError("missing slice" + std::string(absent > 1 ? "s " : " ") + missing + " (" +
                     std::to_string(by_index.size()) + " of " + std::to_string(n) + " given)");
  }
  std::string out = first.columns;
  for (const auto& [k, s] : by_index) out += s->rows;
  if (command) *command = first.header.command;
  return out;
}

}  // namespace fragsim
