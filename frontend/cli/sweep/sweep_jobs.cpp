// A sweep that outgrows one machine goes to an engine made for it: a job list for GNU parallel (one shell
// line per run, `parallel < jobs.txt`, `--sshloginfile` for many machines) and a Slurm job array (one array
// task per run, each running its line of the job list, and a collect job after them). Every path in them
// is absolute, so they run from any folder of a cluster that shares the output folder and the recipe.
#include <cstdio>

#include "frontend/cli/commands.h"
#include "frontend/cli/shell_quote.h"
#include "frontend/cli/sweep/sweep.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/param_spec.h"
#include "kernels/base/check.h"
#include "kernels/io/output_file.h"

namespace selfsim::interp {

namespace {

// A line of the job list or a script from words: each quoted by the one rule (shell_quote.h).
std::string words(const std::vector<std::string>& args) {
  std::string line;
  for (const std::string& a : args) line += (line.empty() ? "" : " ") + script_word(a, "a word of the line");
  return line;
}

// The command that builds the sheets and series once every run is done.
std::vector<std::string> collect_arguments(const SweepConfig& c, const std::string& exe,
                                           const std::filesystem::path& out, const std::filesystem::path& recipe) {
  std::vector<std::string> a{exe, "sweep", recipe.string(), "-o", out.string()};
  for (const auto& [key, text] : c.run.sets) a.insert(a.end(), {"--set", key + "=" + text});
  a.push_back("--collect");
  if (!c.sheet) a.push_back("--no-sheet");
  return a;
}

// The longest line of a job list. GNU parallel refuses a command line longer than the system allows less
// the environment (`parallel --max-line-length-allowed`: 130329 on a Linux with a small environment, 63664
// on a tester's, "Command line too long", exit 255, nothing run), and a Slurm task passes its line to
// `bash -c` as one argument (Linux: at most 131072 bytes). Half the smaller, so a line written here runs
// under either, with room for a larger environment on the machines that run it.
constexpr std::size_t max_job_line = 32768;

// The refusal of a job line over max_job_line, naming the run's longest --set value (what makes a line
// long: paths are at most 4096 bytes).
std::string too_long(std::size_t bytes, const SweepRun& run) {
  std::string key, value;
  for (const auto& [k, v] : run.sets)
    if (k.size() + v.size() > key.size() + value.size()) key = k, value = v;
  return "--set " + shown_text(key + "=" + value, 60) + ": the job line of run '" + shown_text(run.folder) +
         "' would be " + std::to_string(bytes) + " bytes; at most " + std::to_string(max_job_line) +
         " in a job list (GNU parallel and Slurm refuse longer lines): run the sweep here, without --jobs-file or "
         "--slurm, or give the recipe the long text in a file";
}

// The job list and Slurm scripts, whole, before any is written.
struct JobLists {
  std::string list, list_path, jobs;                     // the job list's name, path and text
  std::string collect;                                   // the collect command's line
  std::string array_text, collect_script, collect_text;  // with --slurm
};

JobLists job_lists(const SweepConfig& c, const SweepPlan& plan, const std::string& exe) {
  const std::filesystem::path out = std::filesystem::absolute(c.run.out_dir).lexically_normal();
  const std::filesystem::path recipe = std::filesystem::absolute(c.run.recipe).lexically_normal();
  // Every text that reaches a line, by where it came from, so a refusal names it; words() below refuses
  // the same for any word at all.
  script_word(exe, "selfsim's own path");
  script_word(recipe.string(), "the recipe's path");
  script_word(out.string(), "the output folder");
  script_word(c.jobs_file, "--jobs-file");
  script_word(c.slurm, "--slurm");
  for (const auto& [key, text] : c.run.sets) script_word(key + "=" + text, "--set");
  const int threads = c.run.threads > 0 ? c.run.threads : 1;
  SweepConfig absolute = c;
  absolute.run.recipe = recipe;
  JobLists j;
  for (const SweepRun& run : plan.runs) {
    const std::string dir = (out / run.folder).string();
    std::vector<std::string> a = run_arguments(absolute.run, run, dir, threads);
    a.insert(a.begin(), exe);
    // The run's messages go to its log and its exit code beside them, which --collect reads.
    // As in a local sweep, the folder is the run's alone: an earlier sweep's files are removed first.
    const std::string line = words({"rm", "-rf", dir}) + " && " + words({"mkdir", "-p", dir}) + " && " + words(a) +
                             " >" + words({dir + "/selfsim.log"}) + " 2>&1; echo $? >" + words({dir + "/selfsim.exit"});
    if (line.size() > max_job_line) throw UsageError(too_long(line.size(), run));
    j.jobs += line + "\n";
  }
  j.list = c.jobs_file.empty() ? "jobs.txt" : c.jobs_file;
  j.list_path = (out / j.list).string();
  j.collect = words(collect_arguments(c, exe, out, recipe));
  if (c.slurm.empty()) return j;
  // sbatch reads #SBATCH lines itself, not through a shell: a path is double-quoted (a space would end
  // it) and its '%' doubled (Slurm expands %j, %a, ... in it, and %% to %). A '\' cannot be written at
  // all: sbatch's parser reads it as an escape, even inside quotes, and Slurm expands no %a in a file name
  // that still holds one (written '\\'; sbatch(1), "filename pattern"), so every array task would write the
  // one log. It is refused, as a '"' (which would end the quoting) and a line break are.
  const std::string folder = (out / "slurm").string();
  if (const std::size_t at = folder.find_first_of("\"\\\n\r"); at != std::string::npos) {
    const char ch = folder[at];
    throw UsageError(std::string("--slurm: the output folder's path holds ") +
                     (ch == '"'    ? "a '\"', which would end the quoted file name of an #SBATCH --output line"
                      : ch == '\\' ? "a '\\', which Slurm reads in an #SBATCH --output file name as an escape that "
                                     "turns off its %a (every array task would write one log)"
                                   : "a line break, which an #SBATCH line cannot") +
                     ": choose another output folder with -o");
  }
  std::string logs;
  for (char ch : folder) logs += ch == '%' ? std::string("%%") : std::string(1, ch);
  auto output = [&](const std::string& leaf) { return "#SBATCH --output=\"" + logs + "/" + leaf + "\"\n"; };
  j.array_text =
      "#!/bin/bash\n# One Slurm array task per run of the sweep of " + script_comment(recipe.filename().string()) +
      " (" + std::to_string(plan.runs.size()) + " runs): task i runs line i + 1 of " + script_comment(j.list) + ".\n" +
      "#SBATCH --job-name=selfsim-sweep\n#SBATCH --array=0-" + std::to_string(plan.runs.size() - 1) +
      "\n#SBATCH --cpus-per-task=" + std::to_string(threads) + "\n" + output("run-%a.out") +
      "line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " + words({j.list_path}) + ")\nexec bash -c \"$line\"\n";
  j.collect_script = "collect-" + c.slurm;
  j.collect_text =
      "#!/bin/bash\n# The sheets and ParaView series of the sweep, once its array has ended.\n"
      "#SBATCH --job-name=selfsim-collect\n" +
      output("collect.out") + j.collect + "\n";
  return j;
}

}  // namespace

std::vector<std::string> run_arguments(const RunConfig& r, const SweepRun& run, const std::filesystem::path& dir,
                                       int threads) {
  std::vector<std::string> a{"run", r.recipe.string(), "-o", dir.string()};
  for (const auto& [key, value] : run.sets) a.insert(a.end(), {"--set", key + "=" + escaped_value(value)});
  if (r.max_points != default_max_points) a.insert(a.end(), {"--max-points", number_text(r.max_points)});
  if (r.max_memory > 0) a.insert(a.end(), {"--max-memory", number_text(r.max_memory)});
  if (r.timeout > 0) a.insert(a.end(), {"--timeout", number_text(r.timeout)});
  if (r.seed != 0) a.insert(a.end(), {"--seed", std::to_string(r.seed)});
  if (threads > 0) a.insert(a.end(), {"--threads", std::to_string(threads)});
  if (!r.view) a.push_back("--no-view");
  a.push_back("-q");
  return a;
}

void check_job_lists(const SweepConfig& c, const SweepPlan& plan, const std::string& exe) { job_lists(c, plan, exe); }

int write_job_lists(const SweepConfig& c, const SweepPlan& plan, const std::string& exe) {
  const JobLists j = job_lists(c, plan, exe);
  const std::filesystem::path out = std::filesystem::absolute(c.run.out_dir).lexically_normal();
  io::write_whole(out, j.list, j.jobs);
  if (!c.run.quiet) {
    std::printf("wrote %s (%zu runs)\n", shown_text(j.list_path).c_str(), plan.runs.size());
    if (!c.jobs_file.empty())
      std::printf(
          "  run it here:           parallel --jobs 2 < %s\n"
          "  or on many machines:   parallel --sshloginfile nodes.txt --jobs 1 < %s\n"
          "  (the recipe, the output folder and selfsim at the same paths on every machine)\n"
          "  then the sheets:       %s\n",
          shell_word(j.list_path).c_str(), shell_word(j.list_path).c_str(), j.collect.c_str());
  }
  if (c.slurm.empty()) return 0;
  io::make_folder(out, "slurm");  // confined, as every write: a link there is refused
  io::write_whole(out, c.slurm, j.array_text);
  io::write_whole(out, j.collect_script, j.collect_text);
  const std::string array = shell_word((out / c.slurm).string()), after = shell_word((out / j.collect_script).string());
  if (!c.run.quiet)
    std::printf("wrote %s and %s\n  submit: jid=$(sbatch --parsable %s) && sbatch --dependency=afterany:$jid %s\n",
                array.c_str(), after.c_str(), array.c_str(), after.c_str());
  return 0;
}

}  // namespace selfsim::interp
