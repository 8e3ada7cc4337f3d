#include "kernels/io/view/series_file.h"

#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/base/utf8.h"
#include "kernels/io/output_file.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/json_text.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

namespace {

struct SeriesName {
  std::filesystem::path folder;  // where the series file is, relative to root
  std::string stem;              // "growth"
  std::string step_extension;    // ".vtp" or ".vtu"
  bool json = false;             // .series rather than .pvd
};

bool ends_with(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

SeriesName parse_name(const std::string& name) {
  const std::filesystem::path p(name);
  const std::string leaf = p.filename().string(), lower = lower_case(leaf);
  SeriesName n{p.parent_path(), "", ".vtp", false};
  if (ends_with(lower, ".pvd")) {
    n.stem = leaf.substr(0, leaf.size() - 4);
  } else if (ends_with(lower, ".series")) {
    n.json = true;
    // ParaView matches ".vtp.series" case-sensitively: "X.VTP.SERIES" would find no reader.
    const std::string end = lower.substr(lower.size() - std::min<std::size_t>(lower.size(), 11));
    if ((end == ".vtp.series" || end == ".vtu.series") && !ends_with(leaf, end))
      throw Error("'" + name + "': ParaView reads a .series file only when its extension is in lower case, '" +
                  leaf.substr(0, leaf.size() - 11) + end + "'");
    const std::string inner = lower.substr(0, lower.size() - 7);
    if (!ends_with(inner, ".vtp") && !ends_with(inner, ".vtu")) {
      const std::string before = std::filesystem::path(leaf.substr(0, leaf.size() - 7)).extension().string();
      const std::string stem = leaf.substr(0, leaf.size() - 7 - before.size());
      throw Error("'" + name + "': ParaView picks a .series file's reader from the extension before '.series', which " +
                  (before.empty() ? std::string("is missing") : "must be .vtp or .vtu, not '" + before + "'") +
                  "; name it '" + stem + ".vtp.series'");
    }
    n.step_extension = inner.substr(inner.size() - 4);
    n.stem = leaf.substr(0, inner.size() - 4);
  } else {
    throw Error("'" + name + "' is not a series name: give it the extension .pvd or .vtp.series");
  }
  // ParaView reads a series' names as UTF-8 paths in which a backslash separates folders.
  if (name.find('\\') != std::string::npos)
    throw Error("'" + name + "': a series name cannot hold a backslash (ParaView reads it as a folder separator)");
  if (!valid_utf8(name)) throw Error("a series name must be UTF-8 text (ParaView's readers cannot name its steps)");
  if (!xml_holds(name))
    throw Error("a series name must hold no control character, U+FFFE or U+FFFF (no .pvd can name its steps)");
  if (n.stem.empty() || n.stem == "." || n.stem == "..")
    throw Error("'" + name + "': a series needs a name before its extension, such as 'growth.pvd'");
  return n;
}

std::string step_leaf(const SeriesName& n, std::size_t i, std::size_t count) {
  std::string digits = std::to_string(i);
  const std::size_t width = std::max<std::size_t>(3, std::to_string(count == 0 ? 0 : count - 1).size());
  digits.insert(0, width - digits.size(), '0');
  return n.stem + "_" + digits + n.step_extension;
}

// Whether `leaf` is named as this series names its steps: stem_DIGITS.ext.
bool is_step_leaf(const SeriesName& n, const std::string& leaf) {
  const std::string prefix = n.stem + "_";
  if (leaf.size() <= prefix.size() + n.step_extension.size() || leaf.compare(0, prefix.size(), prefix) != 0 ||
      !ends_with(leaf, n.step_extension))
    return false;
  const std::string digits = leaf.substr(prefix.size(), leaf.size() - prefix.size() - n.step_extension.size());
  return digits.find_first_not_of("0123456789") == std::string::npos;
}

std::string time_text(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", t);
  return buffer;
}

}  // namespace

std::string pvd_text(const std::vector<std::string>& files, std::span<const double> times) {
  std::string s =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (std::size_t i = 0; i < files.size(); ++i)
    s += "    <DataSet timestep=\"" + time_text(times[i]) + "\" group=\"\" part=\"0\" file=\"" + xml_escaped(files[i]) +
         "\"/>\n";
  return s + "  </Collection>\n</VTKFile>\n";
}

namespace {

std::string series_text(const std::vector<std::string>& files, std::span<const SeriesStep> steps) {
  std::string s = "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
  for (std::size_t i = 0; i < files.size(); ++i)
    s += "    { \"name\" : \"" + json_escaped(files[i]) + "\", \"time\" : " + time_text(steps[i].time) + " }" +
         (i + 1 < files.size() ? ",\n" : "\n");
  return s + "  ]\n}\n";
}

// The quoted strings after each `key` (after a space or at the start) followed by '=' (XML) or ':' (JSON),
// without their quotes, entities (XML) or backslash escapes (JSON) undone. A plain scan: a crafted file of
// any length costs one pass and no recursion.
std::vector<std::string> quoted_values(const std::string& text, const std::string& key, bool json) {
  std::vector<std::string> out;
  auto space = [&](std::size_t& i) {
    while (i < text.size() && xml_space(text[i])) ++i;
  };
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
    if (!json && at > 0 && !xml_space(text[at - 1])) continue;  // an attribute, not the end of another's name
    std::size_t i = at + key.size();
    space(i);
    if (i >= text.size() || (text[i] != '=' && text[i] != ':')) continue;
    ++i;
    space(i);
    if (i >= text.size() || text[i] != '"') continue;
    std::string value;
    for (++i; i < text.size() && text[i] != '"'; ++i) {
      if (json && text[i] == '\\' && i + 1 < text.size()) ++i;
      value += text[i];
    }
    if (i >= text.size()) break;
    out.push_back(json ? std::move(value) : xml_unescaped(std::move(value)));
  }
  return out;
}

// The text of a series file, at most 64 MiB.
std::string series_file_text(const std::filesystem::path& series) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(series, ec);
  if (ec || !std::filesystem::is_regular_file(series, ec))
    throw Error(cannot_read(series, ec ? ec.message() : "not a regular file"));
  if (size > (std::uintmax_t{64} << 20)) throw Error(cannot_read(series, "a series file over 64 MiB"));
  std::ifstream in(series, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

std::vector<double> read_series_times(const std::filesystem::path& series) {
  const bool json = ends_with(lower_case(series.filename().string()), ".series");
  const std::string text = series_file_text(series);
  std::vector<double> times;
  auto number = [&](const char* at) {
    char* end = nullptr;
    const double t = std::strtod(at, &end);
    if (end == at || !std::isfinite(t)) return false;
    times.push_back(t);
    return true;
  };
  if (!json) {
    for (const std::string& t : quoted_values(text, "timestep", false))
      if (!number(t.c_str())) return {};
    return times;
  }
  // JSON: "time" : NUMBER, the number not quoted.
  for (std::size_t at = text.find("\"time\""); at != std::string::npos; at = text.find("\"time\"", at + 1)) {
    std::size_t i = at + 6;
    while (i < text.size() && xml_space(text[i])) ++i;
    if (i >= text.size() || text[i] != ':') continue;
    ++i;
    while (i < text.size() && xml_space(text[i])) ++i;
    if (!number(text.c_str() + i)) return {};
  }
  return times;
}

std::vector<std::filesystem::path> read_series_steps(const std::filesystem::path& series) {
  const bool json = ends_with(lower_case(series.filename().string()), ".series");
  const std::string text = series_file_text(series);
  std::vector<std::filesystem::path> steps;
  for (const std::string& name : quoted_values(text, json ? "\"name\"" : "file", json)) {
    const std::filesystem::path p = std::filesystem::path(name).lexically_normal();
    if (name.find('\0') != std::string::npos)
      throw Error(cannot_read(series, "it names a step with a NUL byte in its name"));
    if (p.empty() || p.is_absolute() || *p.begin() == "..")
      throw Error(cannot_read(series, "it names a step outside its folder ('" + one_line(name) + "')"));
    steps.push_back(series.parent_path() / p);
  }
  if (steps.empty()) throw Error(cannot_read(series, "it names no step (not a .pvd Collection or .series file)"));
  return steps;
}

bool is_series_name(const std::string& name) {
  const std::string lower = lower_case(std::filesystem::path(name).filename().string());
  return ends_with(lower, ".pvd") || ends_with(lower, ".series");
}

std::string series_step_extension(const std::string& name) { return parse_name(name).step_extension; }

std::vector<std::string> series_step_names(const std::string& name, std::size_t count) {
  const SeriesName n = parse_name(name);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < count; ++i) names.push_back((n.folder / n.stem / step_leaf(n, i, count)).string());
  return names;
}

SeriesFiles save_series(std::span<const SeriesStep> steps, const std::filesystem::path& root, const std::string& name,
                        const SaveOptions& opt, Progress& progress) {
  const SeriesName n = parse_name(name);
  if (steps.empty()) throw Error("a series needs at least one step");
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!std::isfinite(steps[i].time))
      throw Error("the time of step " + std::to_string(i + 1) + " is not a finite number");
    if (i > 0 && !(steps[i].time > steps[i - 1].time))
      throw Error("the times of a series must increase: step " + std::to_string(i + 1) + " has " +
                  number_text(steps[i].time) + " after " + number_text(steps[i - 1].time));
  }
  // The steps the series file there now names (an earlier run's): once the new one is in place, those it
  // does not name are removed, and nothing else in the folder is.
  std::set<std::string> old_steps;
  std::error_code ec;
  if (std::filesystem::is_regular_file(root / name, ec)) try {
      for (const std::filesystem::path& p : read_series_steps(root / name))
        if (p.parent_path() == (root / n.folder / n.stem).lexically_normal()) old_steps.insert(p.filename().string());
    } catch (const Error&) {
      // Not a series we can read: nothing of it is removed.
    }
  const std::filesystem::path folder = n.folder / n.stem;
  {
    struct stat st {};
    if (::lstat((root / folder).c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
      throw Error("'" + name + "' writes its steps into the folder '" + folder.string() + "/', but '" +
                  folder.string() + "' is " + (S_ISLNK(st.st_mode) ? "a symbolic link" : "a file") +
                  "; give the series another name");
  }
  // Each step is written whole under a hidden name first; only when every step is there are they renamed
  // into place and the series file written. A run that fails or is stopped before then leaves the old
  // series as it was, its steps untouched.
  auto hidden = [&](const std::string& leaf) { return "." + leaf + ".new" + n.step_extension; };
  // Never throws: it runs while another error is on its way, and before a write that reports its own.
  auto remove_hidden = [&]() noexcept {
    std::error_code missing;
    if (!std::filesystem::is_directory(std::filesystem::symlink_status(root / folder, missing))) return;
    try {
      remove_files(root, folder, [&](const std::string& leaf) {
        const std::string end = ".new" + n.step_extension;
        return leaf.size() > 1 + end.size() && leaf[0] == '.' && ends_with(leaf, end) &&
               is_step_leaf(n, leaf.substr(1, leaf.size() - 1 - end.size()));
      });
    } catch (const std::exception&) {
      // A folder we cannot list holds no hidden steps of ours to remove.
    }
  };
  remove_hidden();  // a killed earlier run's
  SeriesFiles written;
  std::vector<std::string> in_series, leaves;  // in_series: relative to the series file's folder
  try {
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::string leaf = step_leaf(n, i, steps.size());
      try {
        save(steps[i].value, root, (folder / hidden(leaf)).string(), opt, progress);
      } catch (const Cancelled&) {
        throw;
      } catch (const BudgetError&) {
        throw;
      } catch (const Error& e) {
        throw Error("step " + std::to_string(i + 1) + " of '" + name + "': " + e.what());
      }
      leaves.push_back(leaf);
      in_series.push_back((std::filesystem::path(n.stem) / leaf).generic_string());
      written.steps.push_back((folder / leaf).string());
    }
    if (progress.cancelled()) throw Cancelled();
  } catch (...) {
    remove_hidden();
    throw;
  }
  for (const std::string& leaf : leaves) rename_file(root, folder, hidden(leaf), leaf);
  OutputFile out(root, name);
  std::vector<double> times;
  for (const SeriesStep& step : steps) times.push_back(step.time);
  out.write(n.json ? series_text(in_series, steps) : pvd_text(in_series, times));
  out.commit();
  written.series = out.path();
  const std::set<std::string> kept(leaves.begin(), leaves.end());
  remove_files(root, folder, [&](const std::string& leaf) {
    return old_steps.count(leaf) && !kept.count(leaf) && is_step_leaf(n, leaf);
  });
  return written;
}

}  // namespace selfsim::io
