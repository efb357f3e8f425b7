// The ocean command-line tool: one subcommand per file (commands/*.cpp). main() is the last line
// of defence of the one-line error contract: an exception that escapes a command becomes one
// `ocean: error:` line and exit 1, never an abort; and output that could not be written to
// standard output (a full disk, /dev/full) fails the run instead of passing for success.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/core.hpp"

namespace {

// What the tool is doing, for "out of memory: <doing>". A fixed buffer: reporting must not
// allocate, and it outlives the command line parser, which the exception has destroyed.
struct Doing {
  char text[128] = "reading the command line";
};

int run(int argc, char** argv, Doing& doing) {
  CLI::App app{"ocean — spectral ocean surface simulation: spectra, dispersion, spreading"};
  app.name("ocean");
  app.require_subcommand(1);
  const std::vector<ocean::cli::Command> commands = ocean::cli::add_commands(app);
  // CLI11 would only say "A subcommand is required": name the word it did not know.
  std::string names;
  bool known = argc < 2 || argv[1][0] == '-';
  for (const ocean::cli::Command& command : commands) {
    names.append(names.empty() ? "" : ", ").append(command.app->get_name());
    known = known || command.app->check_name(argv[1]);
  }
  if (!known) {
    std::cerr << "ocean: error: unknown command '" << ocean::excerpt(argv[1])
              << "' (commands: " << names << "; see ocean --help)\n";
    return ocean::cli::kExitUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help: printed on stdout, exit 0
    std::cerr << "ocean: error: " << e.what() << " (see ocean --help)\n";
    return ocean::cli::kExitUsage;
  }
  for (const ocean::cli::Command& command : commands) {
    if (command.app->parsed()) {
      // An empty value is a usage error, never the flag left out: one check for every flag.
      if (ocean::Status s = ocean::cli::refuse_empty_values(*command.app); !s.ok())
        return ocean::cli::report(s);
      std::snprintf(doing.text, sizeof doing.text, "running ocean %s",
                    command.app->get_name().c_str());
      return command.run();
    }
  }
  return ocean::cli::kExitUsage;
}

int fail(const char* message) {
  std::fprintf(stderr, "ocean: error: %s\n", message);
  return ocean::cli::kExitFailure;
}

// Flushes standard output; a write that failed now or earlier fails a run that had succeeded
// (one that failed has said why already). A failure reported earlier leaves no errno: the
// stream only remembers that it failed.
int finish_output(int code) {
  errno = 0;
  std::cout.flush();  // synchronised with stdio: fflush(stdout), whose failure empties the buffer
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (flushed && !std::cout.fail() && std::ferror(stdout) == 0) return code;
  if (code != ocean::cli::kExitOk) return code;
  std::fprintf(stderr, "ocean: error: cannot write standard output%s%s\n", err != 0 ? ": " : "",
               err != 0 ? std::strerror(err) : "");
  return ocean::cli::kExitFailure;
}

}  // namespace

int main(int argc, char** argv) {
  Doing doing;
  int code = ocean::cli::kExitFailure;
  try {
    code = run(argc, argv, doing);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "ocean: error: out of memory: %s\n", doing.text);
  } catch (const std::exception& e) {
    try {
      code = fail(ocean::excerpt(e.what(), 200).c_str());
    } catch (...) {
      code = fail("unexpected failure");
    }
  } catch (...) {
    code = fail("unexpected failure");
  }
  return finish_output(code);
}
