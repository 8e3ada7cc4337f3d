// The one rule for text that selfsim writes for a shell to read: the lines of a sweep's job list, its Slurm
// scripts, and the commands its messages suggest. Every path, value, name and option goes through
// shell_word (or script_word, for a line of a file), so that none of them can become a command of its own.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace selfsim::interp {

// One word for a POSIX shell: as it is when every byte is a letter, digit or one of _-.,/=:+@% (none of
// which a shell expands), else in single quotes, a ' written as '\''. Inside single quotes a shell takes
// every byte as it is: $( ), backticks, ;, quotes, non-UTF-8 bytes, and a line break, which stays in the
// word but splits a line of a file that is read line by line (see script_word).
std::string shell_word(std::string_view word);

// "selfsim run a.lua --set 'name=two words'": the command line of `args`, for messages that suggest it.
std::string shell_command(const std::vector<std::string>& args);

// A word for one line of a file selfsim generates (a job list, a Slurm script): shell_word's quoting, and a
// line break (\n or \r) refused, since GNU parallel, sed and sbatch read these files line by line and no
// quoting that every shell reads keeps a line break on one line. Throws UsageError naming `what` ("the
// recipe's path") and the text.
std::string script_word(std::string_view word, const std::string& what);

// Text for a comment line of a generated script: every control byte (a line break above all, which would
// end the comment and start a command) shown as '?'.
std::string script_comment(std::string_view text);

}  // namespace selfsim::interp
