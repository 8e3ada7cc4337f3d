#include "kernels/io/run_results.h"

#include <charconv>
#include <cmath>
#include <set>

#include "kernels/base/error.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"
#include "kernels/io/text/json_text.h"

namespace selfsim::io {

namespace {

bool name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool name_char(char c) { return name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }

// results.json is small (a name and a number per result): anything far larger is not one.
constexpr std::uint64_t max_results_bytes = 16u << 20;

// A reader for exactly what results_json writes (whitespace between tokens allowed, as JSON allows).
class Parser {
 public:
  explicit Parser(const std::string& text) : t_(text) {}

  std::vector<RunResult> read() {
    need('{', "'{' at the start");
    need_key("results");
    need('{', "'{' opening \"results\"");
    std::vector<RunResult> results;
    std::set<std::string> seen;
    if (!eat('}')) {
      do {
        RunResult r;
        r.name = name();
        if (!seen.insert(r.name).second) throw Error("the result \"" + r.name + "\" is given twice");
        if (seen.size() > max_results)
          throw Error("it holds more than " + std::to_string(max_results) + " results, the most a run gives");
        need(':', "':' after \"" + r.name + "\"");
        r.value = number(r.name);
        results.push_back(std::move(r));
      } while (eat(','));
      need('}', "',' or '}' after a result");
    }
    need(',', "',' after \"results\"");
    need_key("provenance");
    // The rest is the provenance record and the closing '}'.
    std::size_t end = t_.size();
    while (end > i_ && is_space(t_[end - 1])) --end;
    if (end == i_ || t_[end - 1] != '}') throw Error("expected '}' at the end");
    if (!parse_provenance(t_.substr(i_, end - 1 - i_)))
      throw Error("expected the provenance record after \"provenance\"");
    return results;
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  void skip() {
    while (i_ < t_.size() && is_space(t_[i_])) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < t_.size() && t_[i_] == c) return ++i_, true;
    return false;
  }
  void need(char c, const std::string& what) {
    if (!eat(c)) throw Error("expected " + what + ", found " + found());
  }
  std::string found() const {
    return i_ < t_.size() ? "'" + shown(std::string_view(t_).substr(i_, 12)) + "'" : "the end";
  }
  // A quoted name: result names need no escapes, so a backslash is refused with the rest.
  std::string name() {
    need('"', "a result's name in quotes");
    const std::size_t close = t_.find('"', i_);
    if (close == std::string::npos) throw Error("a result's name is not closed with '\"'");
    std::string n = t_.substr(i_, close - i_);
    i_ = close + 1;
    if (const std::string problem = result_name_problem(n); !problem.empty())
      throw Error("the result name \"" + shown(n) + "\" " + problem);
    return n;
  }
  void need_key(const std::string& key) {
    need('"', "\"" + key + "\"");
    if (t_.compare(i_, key.size() + 1, key + "\"") != 0) throw Error("expected \"" + key + "\"");
    i_ += key.size() + 1;
    need(':', "':' after \"" + key + "\"");
  }
  // A JSON number: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?, finite as a double.
  double number(const std::string& name) {
    skip();
    const std::size_t begin = i_;
    auto digits = [&] {
      const std::size_t from = i_;
      while (i_ < t_.size() && t_[i_] >= '0' && t_[i_] <= '9') ++i_;
      return i_ - from;
    };
    if (i_ < t_.size() && t_[i_] == '-') ++i_;
    const std::size_t whole = i_;
    bool ok = digits() > 0 && !(t_[whole] == '0' && i_ - whole > 1);
    if (ok && i_ < t_.size() && t_[i_] == '.') ++i_, ok = digits() > 0;
    if (ok && i_ < t_.size() && (t_[i_] == 'e' || t_[i_] == 'E')) {
      ++i_;
      if (i_ < t_.size() && (t_[i_] == '+' || t_[i_] == '-')) ++i_;
      ok = digits() > 0;
    }
    double v = 0;
    if (ok) {
      const auto r = std::from_chars(t_.data() + begin, t_.data() + i_, v);
      ok = r.ec == std::errc() && r.ptr == t_.data() + i_ && std::isfinite(v);
    }
    if (!ok) {
      i_ = begin;
      throw Error("expected a finite number for \"" + name + "\", found " + found());
    }
    return v;
  }

  const std::string& t_;
  std::size_t i_ = 0;
};

}  // namespace

std::string result_name_problem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.size() > max_result_name)
    return "is " + std::to_string(name.size()) + " bytes long; at most " + std::to_string(max_result_name);
  if (!name_start(name[0])) return "must start with a letter or '_'";
  for (char c : name)
    if (!name_char(c))
      return "holds '" + one_line(std::string(1, c)) +
             "': a result name is letters, digits, '_', '-' and '.' (it names a CSV column and a plot file)";
  return "";
}

std::string results_json(const std::vector<RunResult>& results, const std::string& provenance) {
  std::string s = "{\"results\": {";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const RunResult& r = results[i];
    if (const std::string problem = result_name_problem(r.name); !problem.empty())
      throw Error("the result name '" + shown(r.name) + "' " + problem);
    if (!std::isfinite(r.value)) throw Error("the result '" + r.name + "' is not a finite number");
    s += (i ? ", " : "") + json_string(r.name) + ": " + json_number(r.value);
  }
  return s + "},\n \"provenance\": " + provenance + "}\n";
}

std::vector<RunResult> parse_results(const std::string& text) { return Parser(text).read(); }

std::optional<std::vector<RunResult>> read_results(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / results_file;
  std::error_code ec;
  const auto st = std::filesystem::symlink_status(file, ec);
  if (!std::filesystem::exists(st)) return std::nullopt;
  try {
    if (std::filesystem::is_symlink(st)) throw Error("is a link, not the run's own record");
    const RegularFile f(file);
    if (f.size() > max_results_bytes) throw Error("is larger than a results record can be");
    std::string text(f.size(), '\0');
    if (f.read_at(0, text.data(), text.size()) != text.size()) throw Error("it shrank while being read");
    return parse_results(text);
  } catch (const Error& e) {
    throw Error(cannot_read(file, e.what()));
  }
}

}  // namespace selfsim::io
