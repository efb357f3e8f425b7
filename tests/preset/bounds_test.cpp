// The bounds of the preset format (ocean/preset.hpp): the size of a preset, the nesting depth of
// a document, the key and value of an override, and the user's text echoed in messages. Each
// bound is checked on both sides of its edge.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "ocean/preset.hpp"

namespace {

namespace fs = std::filesystem;
using ocean::ErrorCode;
namespace preset = ocean::preset;

// `levels` arrays, one inside the other, around nothing: "[[]]" is 2 levels.
std::string nested_arrays(int levels) {
  return std::string(static_cast<std::size_t>(levels), '[') +
         std::string(static_cast<std::size_t>(levels), ']');
}

// {"a": {"a": ... {}}}: `levels` objects, one inside the other.
std::string nested_objects(int levels) {
  std::string text;
  for (int i = 1; i < levels; ++i) text += "{\"a\": ";
  text += "{}";
  text.append(static_cast<std::size_t>(levels - 1), '}');
  return text;
}

// A scratch directory for files, removed at the end of the test.
struct ScratchDir {
  fs::path path = fs::temp_directory_path() / ("preset_bounds_" + std::to_string(::getpid()));
  ScratchDir() { fs::create_directories(path); }
  ~ScratchDir() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return path / name;
  }
};

TEST(PresetBounds, DepthIsCheckedBeforeTheDocumentIsBuilt) {
  // 64 levels parse (and fail on their content); 65 do not parse.
  const auto at_limit = preset::from_json("{\"x\": " + nested_arrays(63) + "}");
  ASSERT_FALSE(at_limit.ok());
  EXPECT_EQ(at_limit.status().message(), "x: unknown key");
  const auto over = preset::from_json("{\"x\": " + nested_arrays(64) + "}");
  ASSERT_FALSE(over.ok());
  EXPECT_EQ(over.status().code(), ErrorCode::invalid_argument);
  EXPECT_EQ(over.status().message(), "the document nests deeper than 64 levels");
  // Far beyond: refused the same way, with the stack untouched.
  EXPECT_EQ(preset::from_json(nested_objects(50000)).status().message(),
            "the document nests deeper than 64 levels");
}

TEST(PresetBounds, DeepFilesAreRefusedAndLeaveTheDocumentAlone) {
  const ScratchDir dir;
  const fs::path deep = dir.write("deep.json", nested_objects(50000));
  const fs::path deep_arrays = dir.write("arrays.json", "{\"foam\": " + nested_arrays(50000) + "}");
  preset::Document doc;
  ASSERT_TRUE(doc.set("choppiness=0.5").ok());
  for (const fs::path& p : {deep, deep_arrays}) {
    const ocean::Status s = doc.merge_preset(p.string(), "--preset");
    EXPECT_EQ(s.code(), ErrorCode::invalid_argument);
    EXPECT_EQ(s.message(), "preset '" + p.string() + "' nests deeper than 64 levels");
  }
  const auto config = doc.config();
  ASSERT_TRUE(config.ok()) << config.status().message();
  EXPECT_EQ(config.value().choppiness, 0.5);
}

TEST(PresetBounds, SizeIsBoundedForTextFilesPipesAndDevices) {
  const std::string limit_message =
      " is larger than 1048576 bytes (1 MiB), the most a preset may hold";
  // Valid JSON either side of the bound: padding with spaces keeps the document {}.
  const std::string fits = "{}" + std::string(preset::kMaxPresetBytes - 2, ' ');
  EXPECT_TRUE(preset::from_json(fits).ok());
  const auto big = preset::from_json(fits + " ");
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.status().message(), "the document" + limit_message);

  const ScratchDir dir;
  preset::Document doc;
  EXPECT_TRUE(doc.merge_preset(dir.write("fits.json", fits).string()).ok());
  const fs::path over = dir.write("over.json", fits + " ");
  const ocean::Status file = doc.merge_preset(over.string());
  EXPECT_EQ(file.code(), ErrorCode::invalid_argument);
  EXPECT_EQ(file.message(), "preset '" + over.string() + "'" + limit_message);
  // A device that never ends: reading stops at the bound.
  EXPECT_EQ(doc.merge_preset("/dev/zero").message(), "preset '/dev/zero'" + limit_message);
  // A pipe fed more than the bound by another process (which dies of SIGPIPE when the reader
  // stops: nothing waits for it).
  const fs::path fifo = dir.path / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string writer = "head -c 3000000 /dev/zero > '" + fifo.string() + "' 2>/dev/null &";
  ASSERT_EQ(std::system(writer.c_str()), 0);
  EXPECT_EQ(doc.merge_preset(fifo.string()).message(),
            "preset '" + fifo.string() + "'" + limit_message);
  // A FIFO nothing writes to: an error after kFifoWaitMs, not a process blocked for ever.
  const fs::path silent = dir.path / "silent.json";
  ASSERT_EQ(::mkfifo(silent.c_str(), 0600), 0);
  const ocean::Status waited = doc.merge_preset(silent.string());
  EXPECT_EQ(waited.code(), ErrorCode::io_error);
  EXPECT_EQ(waited.message(), "cannot read preset '" + silent.string() +
                                  "': no process wrote to the FIFO within 5 s");
  // A FIFO whose writer comes late and writes a preset: read as any file.
  const fs::path late = dir.path / "late.json";
  ASSERT_EQ(::mkfifo(late.c_str(), 0600), 0);
  const std::string late_writer =
      "(sleep 1; printf '{\"seed\": 7}' > '" + late.string() + "') 2>/dev/null &";
  ASSERT_EQ(std::system(late_writer.c_str()), 0);
  EXPECT_TRUE(doc.merge_preset(late.string()).ok());
  // A directory is a read error, not a size one.
  EXPECT_EQ(doc.merge_preset(dir.path.string()).code(), ErrorCode::io_error);
}

TEST(PresetBounds, OverridesBoundTheirKeyValueAndDepth) {
  preset::Document doc;
  const std::string key_at_limit = "foam." + std::string(preset::kMaxKeyBytes - 5, 'k');
  EXPECT_TRUE(doc.set(key_at_limit + "=1").ok());
  const ocean::Status long_key = doc.set(key_at_limit + "k=1", "--set");
  EXPECT_EQ(long_key.code(), ErrorCode::invalid_argument);
  EXPECT_NE(long_key.message().find("': the key is 257 bytes: must be at most 256"),
            std::string::npos)
      << long_key.message();

  const std::string value_at_limit(preset::kMaxValueBytes, 'v');
  EXPECT_TRUE(doc.set("normals=" + value_at_limit).ok());
  const ocean::Status long_value = doc.set("normals=" + value_at_limit + "v", "--set");
  EXPECT_NE(long_value.message().find("': the value is 65537 bytes: must be at most 65536"),
            std::string::npos)
      << long_value.message();

  // One level for "foam", 63 for the value: 64 in all.
  EXPECT_TRUE(doc.set("foam=" + nested_arrays(63)).ok());
  const std::string too_deep = "foam=" + nested_arrays(64);
  EXPECT_EQ(doc.set(too_deep, "--set").message(),
            "--set '" + ocean::excerpt(too_deep) + "': nests deeper than 64 levels");
  EXPECT_EQ(doc.set("foam=" + nested_objects(50000), "--set").code(), ErrorCode::invalid_argument);
  // A key of 64 parts holds a scalar; of 65 parts, nothing.
  std::string parts = "a";
  for (int i = 1; i < preset::kMaxPresetDepth; ++i) parts += ".a";
  EXPECT_TRUE(preset::Document().set(parts + "=1").ok());
  EXPECT_EQ(preset::Document().set(parts + ".a=1", "--set").message(),
            "--set '" + ocean::excerpt(parts + ".a=1") + "': nests deeper than 64 levels");
}

// Every value a user typed comes back as an excerpt: short, one line.
TEST(PresetBounds, MessagesEchoExcerptsOfTheUsersText) {
  const std::string huge(5000, 'x');
  const auto expect_short = [&](const ocean::Status& s) {
    EXPECT_FALSE(s.ok());
    EXPECT_LT(s.message().size(), 300u) << s.message().substr(0, 300);
    EXPECT_NE(s.message().find("... (5"), std::string::npos) << s.message().substr(0, 300);
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
  };
  preset::Document doc;
  expect_short(doc.merge_preset(huge, "--preset"));         // neither a file nor a preset
  expect_short(doc.merge_preset("dir/" + huge + ".json"));  // cannot read
  expect_short(doc.set(huge, "--set"));                     // expected key=value
  expect_short(doc.set("seed." + huge + "=1", "--set"));    // not inside an object
  expect_short(preset::builtin(huge).status());             // unknown built-in
  for (const std::string& json :
       {"{\"" + huge + "\": 1}", "{\"normals\": \"" + huge + "\"}",
        "{\"blue_channel\": \"" + huge + "\"}",
        "{\"sea\": {\"wind_sea\": {\"model\": \"" + huge + "\"}}}",
        "{\"sea\": {\"wind_sea\": {\"spreading\": {\"model\": \"" + huge + "\"}}}}"})
    expect_short(preset::from_json(json).status());
  // A control character typed in a name is escaped, not printed.
  const ocean::Status bell = doc.merge_preset("calm\a", "--preset");
  EXPECT_NE(bell.message().find("calm\\x07"), std::string::npos) << bell.message();
}

// nlohmann::json keeps 512 spaces of indentation: an indent above that read past them (a crash
// at 100000). The indent is held to kMaxPresetIndent, and what is written still parses back.
TEST(PresetBounds, AnIndentBeyondTheLimitIsWrittenAsTheLimit) {
  const ocean::SimulationConfig config = ocean::SimulationConfig{};
  const std::string at_limit = preset::to_json(config, ocean::preset::kMaxPresetIndent);
  EXPECT_EQ(preset::to_json(config, 100000), at_limit);
  EXPECT_EQ(preset::to_json(config, 1 << 30), at_limit);
  EXPECT_NE(at_limit.find(std::string(ocean::preset::kMaxPresetIndent, ' ') + "\""),
            std::string::npos);
  const auto back = preset::from_json(at_limit);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(preset::to_json(back.value()), preset::to_json(config));
}

}  // namespace
