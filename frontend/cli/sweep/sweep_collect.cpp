// What a sweep leaves besides its runs' folders: results.csv and its plots (sweep_results.h); for each file
// the runs wrote, a contact sheet (an SVG grid, one cell per run with its values under it: the run's own SVG,
// or a PNG preview of a 3D result), and for each VTK file a ParaView series over the runs (time = the swept
// value when one number varies, else the run's index), so ParaView's Play steps through the variants. Built
// the same way after a local sweep and by `selfsim sweep --collect` after GNU parallel or Slurm ran the job
// list.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>

#include "frontend/cli/commands.h"
#include "frontend/cli/preview_child.h"
#include "frontend/cli/sweep/sweep.h"
#include "frontend/cli/sweep/sweep_results.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/parse_text.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/output_file.h"
#include "kernels/io/text/url_path.h"
#include "kernels/io/text/xml_text.h"
#include "kernels/io/view/series_file.h"

namespace selfsim::interp {

namespace {

// Files of a run that are the sweep's bookkeeping, not the recipe's results.
bool bookkeeping(const std::string& leaf) {
  return leaf == "selfsim.log" || leaf == "selfsim.exit" || leaf == "view.py" || leaf == io::results_file ||
         leaf[0] == '.';
}

bool previewable(const std::string& ext) {
  for (const char* e : {".vtp", ".vtu", ".stl", ".obj", ".ply", ".vdb", ".pvd", ".series"})
    if (ext == e) return true;
  return false;
}

// Text for the sheet's XML: each byte XML cannot hold (a control character, a byte of no UTF-8 character,
// U+FFFE) shown as '?', then the markup characters escaped.
std::string svg_text(const std::string& text) { return io::xml_escaped(io::xml_shown(text)); }

// Columns of a sheet: one per value of the last key when two keys vary (a true grid), else about square.
std::size_t sheet_columns(const SweepPlan& plan) {
  if (plan.keys.size() == 2) {
    std::set<std::string> values;
    for (const SweepRun& run : plan.runs) values.insert(run.sets.at(plan.keys[1]));
    return values.size();
  }
  return static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(plan.runs.size()))));
}

// The line under a sheet's title that links the sweep's results (sweep_results.h): results.csv and each
// plot, or why there is none. Empty when the runs gave no result (the sheet is as it was before results).
std::string results_links(const SweepResults& r, int y) {
  if (r.names.empty()) return "";
  auto link = [](const std::string& file, const std::string& shown) {
    const std::string href = io::xml_escaped(io::url_path(file));
    return "<a href=\"" + href + "\" xlink:href=\"" + href +
           "\"><tspan fill=\"#0645ad\" text-decoration=\"underline\">" + svg_text(shown) + "</tspan></a>";
  };
  std::string s = "<text class=\"results\" x=\"12\" y=\"" + std::to_string(y) +
                  "\" font-size=\"13\">results: " + link(r.written.front(), r.written.front());
  for (std::size_t i = 0; i < r.plots.size(); ++i) s += " · " + link(r.plots[i], "plot of " + r.names[i]);
  if (!r.no_plot.empty()) s += " · no plot: " + svg_text(r.no_plot);
  return s + "</text>\n";
}

// The sheet of one output: `images[i]` is run i's picture (relative to the sheet) or empty, with `notes[i]`
// saying why there is none; under the title, the line linking `results` (results_links), if the runs gave any.
std::string sheet_svg(const SweepPlan& plan, const std::string& title, const std::vector<std::string>& images,
                      const std::vector<std::string>& notes, const SweepResults& results) {
  constexpr int cell = 220, caption = 24, gap = 12;
  const std::string links = results_links(results, 48);
  const int top = links.empty() ? 40 : 62;
  const std::size_t columns = std::max<std::size_t>(1, sheet_columns(plan));
  const std::size_t rows = (plan.runs.size() + columns - 1) / columns;
  const int width = gap + static_cast<int>(columns) * (cell + gap);
  const int height = top + static_cast<int>(rows) * (cell + caption + gap);
  std::string s =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
      "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" +
      std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
      " " + std::to_string(height) + "\" font-family=\"sans-serif\">\n" +
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" + std::to_string(gap) +
      "\" y=\"26\" font-size=\"16\">" + svg_text(title) + "</text>\n" + links;
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const int x = gap + static_cast<int>(i % columns) * (cell + gap);
    const int y = top + static_cast<int>(i / columns) * (cell + caption + gap);
    const std::string at = "x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(y) + "\"";
    s += "<rect " + at + " width=\"" + std::to_string(cell) + "\" height=\"" + std::to_string(cell) +
         "\" fill=\"none\" stroke=\"#ccc\"/>\n";
    if (!images[i].empty()) {
      const std::string href = io::xml_escaped(io::url_path(images[i]));
      s += "<image " + at + " width=\"" + std::to_string(cell) + "\" height=\"" + std::to_string(cell) + "\" href=\"" +
           href + "\" xlink:href=\"" + href + "\" preserveAspectRatio=\"xMidYMid meet\"/>\n";
    } else {
      s += "<text x=\"" + std::to_string(x + cell / 2) + "\" y=\"" + std::to_string(y + cell / 2) +
           "\" font-size=\"14\" text-anchor=\"middle\" fill=\"#b00\">" + svg_text(notes[i]) + "</text>\n";
    }
    s += "<text x=\"" + std::to_string(x + cell / 2) + "\" y=\"" + std::to_string(y + cell + 17) +
         "\" font-size=\"13\" text-anchor=\"middle\">" + svg_text(plan.runs[i].caption) + "</text>\n";
  }
  return s + "</svg>\n";
}

// Run i's time in a sweep series: the swept value when one key varies and all its values are numbers.
std::vector<double> series_times(const SweepPlan& plan) {
  std::vector<double> times;
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const auto v = plan.keys.size() == 1 ? parse_text<double>(plan.runs[i].sets.at(plan.keys[0])) : std::nullopt;
    times.push_back(v ? *v : static_cast<double>(i));
  }
  for (std::size_t i = 1; i < times.size(); ++i)
    if (!(times[i] > times[i - 1])) {  // values listed out of order: the index keeps the steps in run order
      for (std::size_t j = 0; j < times.size(); ++j) times[j] = static_cast<double>(j);
      break;
    }
  return times;
}

// A run's preview of `leaf`, inside the sweep's previews/ folder.
std::string preview_name(const std::string& folder, const std::string& leaf) {
  return "previews/" + folder + "/" + fitting_name("", leaf, ".png");
}

// The ParaView series of the VTK output `leaf`: NAME_sweep.pvd for NAME.vtp, unless another VTK output of
// the runs has the same NAME (a.vtp and a.vtu) or is named NAME itself; then each such series keeps its
// output's whole name (a.vtp_sweep.pvd, a.vtu_sweep.pvd), so no series replaces another.
std::string series_name(const std::string& leaf, const std::map<std::string, std::vector<bool>>& outputs) {
  const std::string stem = std::filesystem::path(leaf).stem().string();
  bool shared = false;
  for (const auto& [other, have] : outputs) {
    const std::string ext = lower_case(std::filesystem::path(other).extension().string());
    if (other == leaf || (ext != ".vtp" && ext != ".vtu")) continue;
    shared = shared || other == stem || std::filesystem::path(other).stem().string() == stem;
  }
  return fitting_name("", shared ? leaf : stem, "_sweep.pvd");
}

}  // namespace

std::vector<int> read_exit_codes(const std::filesystem::path& out, const SweepPlan& plan) {
  std::vector<int> codes;
  for (const SweepRun& run : plan.runs) {
    const std::filesystem::path file = out / run.folder / "selfsim.exit";
    std::error_code ec;
    int code = -1;
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(file, ec))) {  // never a FIFO or link
      std::ifstream in(file);
      if (!(in >> code)) code = -1;
    }
    codes.push_back(code);
  }
  return codes;
}

int collect_sweep(const SweepConfig& c, const SweepPlan& plan, const std::vector<int>& codes) {
  const std::filesystem::path& out = c.run.out_dir;
  const std::size_t n = plan.runs.size();
  // Each result file name, and which runs wrote it.
  std::map<std::string, std::vector<bool>> outputs;
  for (std::size_t i = 0; i < n; ++i) {
    if (codes[i] != 0) continue;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(out / plan.runs[i].folder, ec)) {
      const std::string leaf = entry.path().filename().string();
      if (!entry.is_regular_file(ec) || bookkeeping(leaf)) continue;
      auto& have = outputs[leaf];
      have.resize(n);
      have[i] = true;
    }
  }
  std::vector<std::string> notes(n);
  for (std::size_t i = 0; i < n; ++i)
    notes[i] = codes[i] < 0    ? "not run"
               : codes[i] == 0 ? "no such file"
                               : "failed (exit " + std::to_string(codes[i]) + ")";
  std::string swept;
  for (const std::string& k : plan.keys) swept += (swept.empty() ? "" : " × ") + k;
  const std::string recipe = c.run.recipe.filename().string();
  // The table of the runs' results and its plots first: the sheets link them.
  const SweepResults results = write_sweep_results(c, plan, codes);
  std::vector<std::string> written = results.written;
  // Two outputs whose sheets would share a name (a.vtp.svg and a.vtp): the second takes its other name.
  std::set<std::string> taken;
  auto unique = [&](const std::string& name, const std::string& other) {
    return taken.insert(name).second ? name : (taken.insert(other), other);
  };

  // Sheets of SVG results, and the previews 3D results need (one display for all of them).
  std::set<std::string> svg_stems;
  for (const auto& [leaf, have] : outputs)
    if (lower_case(std::filesystem::path(leaf).extension().string()) == ".svg")
      svg_stems.insert(std::filesystem::path(leaf).stem().string());
  std::vector<std::string> preview_files, preview_names, preview_leaves;
  for (const auto& [leaf, have] : outputs) {
    if (!c.sheet) break;
    const std::filesystem::path p(leaf);
    const std::string ext = lower_case(p.extension().string());
    std::vector<std::string> images(n);
    if (ext == ".svg") {
      for (std::size_t i = 0; i < n; ++i)
        if (have[i]) images[i] = plan.runs[i].folder + "/" + leaf;
      const std::string sheet =
          unique(fitting_name("sheet_", p.stem().string(), ".svg"), fitting_name("sheet_", leaf, ".svg"));
      io::write_whole(out, sheet, sheet_svg(plan, recipe + ": " + leaf + " over " + swept, images, notes, results));
      written.push_back(sheet);
    } else if (previewable(ext) && !svg_stems.contains(p.stem().string())) {
      for (std::size_t i = 0; i < n; ++i)
        if (have[i]) {
          preview_files.push_back((out / plan.runs[i].folder / leaf).string());
          preview_names.push_back(preview_name(plan.runs[i].folder, leaf));
        }
      preview_leaves.push_back(leaf);
    }
  }
  if (!preview_files.empty()) {
    // Their folders first, confined (a link on the way is an error naming it, as for any write), then the
    // pictures by children under the runs' limits (preview_child.h), writing through the same writer.
    for (const std::string& name : preview_names) io::make_folder(out, std::filesystem::path(name).parent_path());
    // In batches (preview_child.h): a failed batch is a warning, its cells say "no preview".
    PreviewBatches previews(c.run, out, preview_files, preview_names);
    if (!previews.wait()) return 130;
    if (previews.failed())
      std::fprintf(stderr, "selfsim: warning: some previews could not be drawn; their cells say \"no preview\"\n");
    for (const std::string& leaf : preview_leaves) {
      const std::vector<bool>& have = outputs[leaf];
      std::vector<std::string> images(n);
      std::vector<std::string> cell_notes = notes;
      for (std::size_t i = 0; i < n; ++i) {
        const std::string png = preview_name(plan.runs[i].folder, leaf);
        std::error_code ec;
        if (have[i] && std::filesystem::is_regular_file(out / png, ec))
          images[i] = png;
        else if (have[i])
          cell_notes[i] = "no preview";
      }
      const std::string sheet =
          unique(fitting_name("sheet_", leaf, ".svg"), fitting_name("sheet_", leaf + "_preview", ".svg"));
      io::write_whole(out, sheet,
                      sheet_svg(plan, recipe + ": " + leaf + " over " + swept, images, cell_notes, results));
      written.push_back(sheet);
    }
  }

  // A ParaView series over the runs for each VTK file they wrote.
  const std::vector<double> all_times = series_times(plan);
  for (const auto& [leaf, have] : outputs) {
    const std::string ext = lower_case(std::filesystem::path(leaf).extension().string());
    if (ext != ".vtp" && ext != ".vtu") continue;
    // A .pvd names each step's file byte for byte (ParaView opens file= as a path, so no escape would do):
    // a name XML cannot hold (not UTF-8, U+FFFE) gets no series, said once, rather than a file no XML
    // parser reads. The sheet above still shows those runs (its links are URLs, escaped as such).
    if (!io::xml_holds(leaf)) {
      std::fprintf(stderr,
                   "selfsim: warning: no ParaView series of '%s': a .pvd (XML) cannot name a file whose name is "
                   "not UTF-8 text (or holds U+FFFE, U+FFFF); open each run's file\n",
                   shown_text(leaf).c_str());
      continue;
    }
    std::vector<std::string> files;
    std::vector<double> times;
    for (std::size_t i = 0; i < n; ++i)
      if (have[i]) {
        files.push_back(plan.runs[i].folder + "/" + leaf);
        times.push_back(all_times[i]);
      }
    const std::string series = series_name(leaf, outputs);
    io::write_whole(out, series, io::pvd_text(files, times));
    written.push_back(series);
  }

  std::size_t ok = 0;
  for (int code : codes) ok += code == 0;
  if (!c.run.quiet) {
    for (const std::string& w : written) std::printf("wrote %s\n", shown_text((out / w).string()).c_str());
    if (!results.no_plot.empty()) std::printf("no plot of the results: %s\n", shown_text(results.no_plot, 300).c_str());
    std::printf("sweep: %zu of %zu runs ok\n", ok, n);
  }
  if (ok < n) {
    std::string failed;
    std::size_t listed = 0;
    for (std::size_t i = 0; i < n && listed < 5; ++i)
      if (codes[i] != 0) {
        failed += (listed++ ? ", " : "") + plan.runs[i].folder;
      }
    std::fprintf(stderr, "selfsim: %zu of %zu runs %s (%s%s; each folder's selfsim.log says why)\n", n - ok, n,
                 c.collect_only ? "failed or did not run" : "failed", failed.c_str(), n - ok > 5 ? ", ..." : "");
  }
  std::fflush(stdout);
  return ok == n ? 0 : 1;
}

}  // namespace selfsim::interp
