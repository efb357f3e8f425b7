// An empty value is a usage error for every flag that takes one: `--shard ""`, `--cascades ""`,
// `--preset ""` are exit 2 with one line naming the flag, never the flag silently left out. The
// flags are not listed here: each subcommand is registered in this process as the tool
// registers it (ocean::cli::add_commands), and every option of it that takes a value is tried,
// so a flag added later is covered too.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/cli_run.hpp"
#include "commands.hpp"

namespace {

// Each run in a folder of its own, under `timeout`: a tool that ignored the empty value would
// go on to do the command's work (render a picture, run a benchmark) there, and is stopped.
ocean_test::CliRun run_with_empty(const std::vector<std::string>& args) {
  const ocean_test::ScratchDir dir("ocean_empty_value_");
  std::vector<std::string> words = {"60", OCEAN_CLI_PATH};
  words.insert(words.end(), args.begin(), args.end());
  return ocean_test::run_program("timeout", words, dir.path);
}

// Every option of `command` that takes a value, given "" as its own word; and as `--flag=`, which
// the parser refuses itself.
void expect_empty_values_refused(const std::string& command) {
  CLI::App app;
  const std::vector<ocean::cli::Command> commands = ocean::cli::add_commands(app);
  const CLI::App* sub = nullptr;
  for (const ocean::cli::Command& c : commands) {
    if (c.app->get_name() == command) sub = c.app;
  }
  if (sub == nullptr) GTEST_SKIP() << "this build has no `ocean " << command << "`";
  int tried = 0;
  for (const CLI::Option* option : sub->get_options()) {
    if (option->get_items_expected_min() == 0 || !option->nonpositional()) continue;  // a switch
    const std::string flag = option->get_name();
    // A required flag other than this one is given some text, so that the parser gets as far
    // as the values (the check of the values comes before any is read).
    std::vector<std::string> args = {command};
    for (const CLI::Option* other : sub->get_options()) {
      if (other != option && other->get_required())
        args.insert(args.end(), {other->get_name(), "x"});
    }
    std::vector<std::string> spaced = args, joined = args;
    spaced.insert(spaced.end(), {flag, ""});
    joined.push_back(flag + "=");
    const ocean_test::CliRun r = run_with_empty(spaced);
    EXPECT_EQ(r.exit_code, 2) << command << " " << flag << " '': " << r.err;
    EXPECT_TRUE(r.out.empty()) << command << " " << flag << " '' printed: " << r.out;
    EXPECT_EQ(r.err, "ocean: error: " + flag + " is empty: give a value or leave the flag out\n")
        << command << " " << flag << " ''";
    // `--flag=` is the parser's own usage error, naming the flag.
    const ocean_test::CliRun eq = run_with_empty(joined);
    EXPECT_EQ(eq.exit_code, 2) << command << " " << flag << "=: " << eq.err;
    EXPECT_EQ(eq.err.rfind("ocean: error: " + flag + ": ", 0), 0u) << eq.err;
    EXPECT_EQ(ocean_test::line_count(eq.err), 1) << eq.err;
    ++tried;
    // The first flag that fails says it: the rest would only repeat it (and take their time).
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(tried, 0) << command;
}

TEST(EmptyValues, Spectrum) { expect_empty_values_refused("spectrum"); }
TEST(EmptyValues, Dispersion) { expect_empty_values_refused("dispersion"); }
TEST(EmptyValues, Spreading) { expect_empty_values_refused("spreading"); }
TEST(EmptyValues, Stats) { expect_empty_values_refused("stats"); }
TEST(EmptyValues, Bake) { expect_empty_values_refused("bake"); }
TEST(EmptyValues, Bench) { expect_empty_values_refused("bench"); }
TEST(EmptyValues, Validate) { expect_empty_values_refused("validate"); }
TEST(EmptyValues, Lod) { expect_empty_values_refused("lod"); }
TEST(EmptyValues, Query) { expect_empty_values_refused("query"); }
TEST(EmptyValues, Render) { expect_empty_values_refused("render"); }
TEST(EmptyValues, View) { expect_empty_values_refused("view"); }
TEST(EmptyValues, Xr) { expect_empty_values_refused("xr"); }

// --shard, --cascades, --resolution and --preset by name, and an empty item among the values of a
// repeatable flag.
TEST(EmptyValues, NamedFlagsAndRepeatedItems) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"bake", "--out", "o", "--shard", ""},
        {"bake", "--out", "o", "--cascades", ""},
        {"bake", "--out", "o", "--resolution", ""},
        {"bake", "--out", "o", "--preset", ""},
        {"bake", "--out", "o", "--format", "npy", ""},
        {"bake", "--out", "o", "--set", "seed=2", "--set", ""}}) {
    const ocean_test::CliRun r = run_with_empty(args);
    const std::string flag = args[args.size() - 2] == "npy" ? "--format" : args[args.size() - 2];
    EXPECT_EQ(r.exit_code, 2) << flag << ": " << r.err;
    EXPECT_EQ(r.err, "ocean: error: " + flag + " is empty: give a value or leave the flag out\n");
  }
}

}  // namespace
