// Pre-authored waveforms: placement, rotation and amplitude of a sampled map, zero outside, and
// reading height maps from .npy and PNG files, hostile ones included.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "ocean/io.hpp"
#include "ocean/waves.hpp"

namespace {

namespace fs = std::filesystem;
using ocean::waves::HeightMap;
using ocean::waves::Waveform;

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("ocean_waveform_" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
};

// 2 rows × 4 columns: value = row·10 + col.
std::shared_ptr<const HeightMap> ramp_map() {
  auto m = std::make_shared<HeightMap>();
  m->rows = 2;
  m->cols = 4;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 4; ++c) m->values.push_back(static_cast<float>(10 * r + c));
  return m;
}

TEST(Waveform, SamplesAtCellCentresAreTheMapTimesAmplitude) {
  // 8 m wide (2 m per column), 4 m deep, centred at (100, 50).
  const Waveform w{.map = ramp_map(), .x_m = 100.0, .z_m = 50.0, .size_m = 8.0, .amplitude_m = 0.5};
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 4; ++c) {
      const double x = 96.0 + 2.0 * c + 1.0, z = 48.0 + 2.0 * r + 1.0;
      EXPECT_DOUBLE_EQ(ocean::waves::waveform_height(w, x, z), 0.5 * (10 * r + c));
    }
  }
  EXPECT_DOUBLE_EQ(ocean::waves::waveform_height(w, 98.0, 49.0), 0.5 * 0.5);  // between columns
  EXPECT_EQ(ocean::waves::waveform_height(w, 95.9, 49.0), 0.0);               // outside
  EXPECT_EQ(ocean::waves::waveform_height(w, 100.0, 52.1), 0.0);
}

TEST(Waveform, RotationTurnsTheMapAboutItsCentre) {
  const Waveform w{.map = ramp_map(),
                   .x_m = 0.0,
                   .z_m = 0.0,
                   .size_m = 8.0,
                   .amplitude_m = 1.0,
                   .rotation_deg = 90.0};
  // Column 3, row 0 sits at map offset (+3, −1); turned by +90° it lands at (+1, +3).
  EXPECT_NEAR(ocean::waves::waveform_height(w, 1.0, 3.0), 3.0, 1e-12);
  EXPECT_NEAR(ocean::waves::waveform_height(w, -1.0, -3.0), 10.0, 1e-12);  // row 1, column 0
}

TEST(HeightMapFile, NpyAndPngReadBack) {
  Scratch s;
  const float values[6] = {-1.0f, 0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
  const std::size_t shape[2] = {2, 3};
  ASSERT_TRUE(ocean::io::write_npy(s.dir / "m.npy", values, shape).ok());
  const auto npy = ocean::waves::load_height_map(s.dir / "m.npy");
  ASSERT_TRUE(npy.ok()) << npy.status().message();
  EXPECT_EQ(npy.value().rows, 2);
  EXPECT_EQ(npy.value().cols, 3);
  EXPECT_EQ(npy.value().values, std::vector<float>(values, values + 6));

  const std::uint16_t gray[4] = {0, 65535, 32768, 16384};
  ASSERT_TRUE(ocean::io::write_png16_gray(s.dir / "m.png", 2, 2, gray).ok());
  const auto png = ocean::waves::load_height_map(s.dir / "m.png");
  ASSERT_TRUE(png.ok()) << png.status().message();
  EXPECT_EQ(png.value().values[0], -1.0f);
  EXPECT_EQ(png.value().values[1], 1.0f);
  EXPECT_NEAR(png.value().values[2], 2.0 * 32768 / 65535 - 1, 1e-7);
}

TEST(HeightMapFile, HostileFilesGiveOneLine) {
  Scratch s;
  const auto fails = [&](const fs::path& path, const std::string& says) {
    const auto m = ocean::waves::load_height_map(path);
    ASSERT_FALSE(m.ok()) << path;
    EXPECT_NE(m.status().message().find(says), std::string::npos) << m.status().message();
    EXPECT_EQ(m.status().message().find('\n'), std::string::npos);
  };
  fails(s.dir / "missing.npy", "No such file");
  std::ofstream(s.dir / "text.npy") << "hello";
  fails(s.dir / "text.npy", "not a NumPy");
  const float v[8] = {};
  const std::size_t three_d[3] = {2, 2, 2};
  ASSERT_TRUE(ocean::io::write_npy(s.dir / "cube.npy", v, three_d).ok());
  fails(s.dir / "cube.npy", "2-D");
  std::string bytes;
  {
    std::ifstream in(s.dir / "cube.npy", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::ofstream(s.dir / "cut.npy", std::ios::binary) << bytes.substr(0, 70);
  fails(s.dir / "cut.npy", "cannot read");
  std::ofstream(s.dir / "fake.png") << "not a png at all";
  fails(s.dir / "fake.png", "cannot read");
  const std::uint8_t rgb[12] = {};
  ASSERT_TRUE(ocean::io::write_png8(s.dir / "rgb.png", 2, 2, 3, rgb).ok());
  fails(s.dir / "rgb.png", "grayscale");
  fails(s.dir / "map.exr", "No such file");
  fails(s.dir / "map.tiff", ".npy, .png or .exr");
  std::ofstream(s.dir / "fake.exr") << "not an exr";
  fails(s.dir / "fake.exr", "cannot read");
  const float rg[8] = {};
  const ocean::io::ExrChannel two[] = {{"R", rg}, {"G", rg + 4}};
  ASSERT_TRUE(
      ocean::io::write_exr(s.dir / "rg.exr", 2, 2, two, ocean::io::ExrPixelType::float32).ok());
  fails(s.dir / "rg.exr", "\"Y\"");
  const float bad[4] = {0.0f, std::numeric_limits<float>::infinity(), 0.0f, 0.0f};
  const ocean::io::ExrChannel inf[] = {{"Y", bad}};
  ASSERT_TRUE(
      ocean::io::write_exr(s.dir / "inf.exr", 2, 2, inf, ocean::io::ExrPixelType::float32).ok());
  fails(s.dir / "inf.exr", "value 1 is not a finite height");
  fails(s.dir, "cannot read");
}

TEST(HeightMapFile, ExrHeightsAreReadAsStoredFromTheirYOrOnlyChannel) {
  Scratch s;
  // 2 rows × 3 columns, row 0 on top of the file = map row 0.
  const float heights[6] = {0.25f, -1.5f, 3.0f, 0.0f, 7.75f, -0.125f};
  const float other[6] = {9, 9, 9, 9, 9, 9};
  const ocean::io::ExrChannel only[] = {{"height", heights}};
  ASSERT_TRUE(
      ocean::io::write_exr(s.dir / "only.exr", 3, 2, only, ocean::io::ExrPixelType::float32).ok());
  const ocean::io::ExrChannel with_y[] = {{"A", other}, {"Y", heights}};
  ASSERT_TRUE(
      ocean::io::write_exr(s.dir / "y.exr", 3, 2, with_y, ocean::io::ExrPixelType::half).ok());
  for (const char* name : {"only.exr", "y.exr"}) {
    SCOPED_TRACE(name);
    const auto m = ocean::waves::load_height_map(s.dir / name);
    ASSERT_TRUE(m.ok()) << m.status().message();
    EXPECT_EQ(m.value().rows, 2);
    EXPECT_EQ(m.value().cols, 3);
    // Every value is exact in half as well (few significant bits).
    EXPECT_EQ(m.value().values, std::vector<float>(heights, heights + 6));
  }
}

// The PNG height map reader walks the chunks before libpng allocates what one declares: this 1×1
// gray file's 'sPLT' chunk declares 1.9 GB (found by the PNG reader's fuzz target).
TEST(HeightMapFile, PngChunkDeclaringMoreThanTheFileIsRefused) {
  Scratch s;
  const unsigned char declares_2gb[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
      0x00, 0x3a, 0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x73, 0x42, 0x49, 0x50, 0x4c,
      0x54, 0x45, 0x54, 0x49, 0x44, 0x41, 0x54, 0x08, 0x99, 0x00, 0x8b, 0x00, 0xc9, 0x73,
      0x42, 0x49, 0x54, 0x73, 0x50, 0x4c, 0x54, 0x45, 0x42, 0x49, 0x54};
  std::ofstream(s.dir / "huge_chunk.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(declares_2gb), sizeof declares_2gb);
  const auto m = ocean::waves::load_height_map(s.dir / "huge_chunk.png");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("chunk 'sPLT' declares 1933723988 bytes, more than the "
                                      "file holds"),
            std::string::npos)
      << m.status().message();
  // A device behind a height map's name is refused before anything is read.
  fs::create_symlink("/dev/zero", s.dir / "zero.npy");
  const auto device = ocean::waves::load_height_map(s.dir / "zero.npy");
  ASSERT_FALSE(device.ok());
  EXPECT_NE(device.status().message().find("it is a character device, not a regular file"),
            std::string::npos)
      << device.status().message();
}

namespace sequence {

// Frame f of a 3 × 4 sequence: every sample = 10·f + column (rows alike).
void write_frame(const fs::path& path, int f, std::size_t rows = 3) {
  std::vector<float> v;
  for (std::size_t r = 0; r < rows; ++r)
    for (int c = 0; c < 4; ++c) v.push_back(static_cast<float>(10 * f + c));
  const std::array<std::size_t, 2> shape{rows, 4};
  ASSERT_TRUE(ocean::io::write_npy(path, v.data(), shape).ok());
}

ocean::Status refusal(const fs::path& pattern) {
  auto frames = ocean::waves::load_height_map_sequence(pattern);
  if (frames.ok()) return {};
  EXPECT_EQ(frames.status().message().find('\n'), std::string::npos);
  return frames.status();
}

}  // namespace sequence

// Frames 1..4 of wave_{frame:03}.npy, played at 2 frames/s: at t the height at a cell centre is
// frame ⌊2t⌋ blended linearly towards the next (W.16), looping (frame 4 → frame 1) or holding.
TEST(WaveformSequence, HeightAtTimeTIsTheFramesBlendedInTime) {
  Scratch s;
  for (int f = 1; f <= 4; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "wave_%03d.npy", f);
    sequence::write_frame(s.dir / name, f);
  }
  sequence::write_frame(s.dir / "wave_7.npy", 7);  // other width: not of the sequence
  auto frames = ocean::waves::load_height_map_sequence(s.dir / "wave_{frame:3}.npy");
  ASSERT_TRUE(frames.ok()) << frames.status().message();
  ASSERT_EQ(frames.value().size(), 4u);  // 001..004
  Waveform w{.frames = frames.value(), .fps_hz = 2.0, .size_m = 4.0, .amplitude_m = 1.0};
  ASSERT_TRUE(ocean::waves::validate(w).ok());
  // Column 1 sits at x = −0.5 (4 columns over 4 m centred at 0); the value there is 10·f + 1 for
  // file number f, i.e. 10·(i + 1) + 1 for frame index i.
  const auto value = [](double index) { return 10.0 * (index + 1.0) + 1.0; };
  EXPECT_DOUBLE_EQ(ocean::waves::waveform_height(w, -0.5, 0.0, 0.0), value(0));
  EXPECT_DOUBLE_EQ(ocean::waves::waveform_height(w, -0.5, 0.0, 1.0), value(2));  // frame 2 at 1 s
  EXPECT_NEAR(ocean::waves::waveform_height(w, -0.5, 0.0, 0.75), value(1.5), 1e-12);
  // Looping: period 4 frames / 2 fps = 2 s; between the last frame and the first at 1.75 s.
  EXPECT_NEAR(ocean::waves::waveform_height(w, -0.5, 0.0, 1.75), 0.5 * (value(3) + value(0)),
              1e-12);
  EXPECT_NEAR(ocean::waves::waveform_height(w, -0.5, 0.0, 2.0 + 1.0), value(2), 1e-12);
  EXPECT_NEAR(ocean::waves::waveform_height(w, -0.5, 0.0, -0.5), value(3), 1e-12);
  w.playback = ocean::waves::Playback::hold;
  EXPECT_DOUBLE_EQ(ocean::waves::waveform_height(w, -0.5, 0.0, 1.75), value(3));
  EXPECT_DOUBLE_EQ(ocean::waves::waveform_height(w, -0.5, 0.0, 100.0), value(3));
  EXPECT_DOUBLE_EQ(ocean::waves::waveform_height(w, -0.5, 0.0, -3.0), value(0));
  EXPECT_EQ(ocean::waves::waveform_height(w, 2.5, 0.0, 1.0), 0.0);  // outside
  // Through the layer: the frame's height at the layer's time.
  ocean::waves::LayerParams p;
  p.area = {.origin_m = {-8.0, -8.0}, .size_m = 16.0, .resolution = 16, .edge_fraction = 0.0};
  p.waveforms.push_back(w);
  auto layer = ocean::waves::LocalLayer::make(p);
  ASSERT_TRUE(layer.ok()) << layer.status().message();
  EXPECT_NEAR(layer.value()->displacement_at(-0.5, 0.0, 0.25)[1], value(0.5), 1e-12);
}

TEST(WaveformSequence, BadSequencesAreRefusedWithOneLine) {
  Scratch s;
  sequence::write_frame(s.dir / "a_0.npy", 0);
  sequence::write_frame(s.dir / "a_1.npy", 1);
  sequence::write_frame(s.dir / "a_3.npy", 3);  // 2 missing
  EXPECT_NE(sequence::refusal(s.dir / "a_{frame}.npy").message().find("frame 2 missing"),
            std::string::npos);
  sequence::write_frame(s.dir / "b_0.npy", 0);
  sequence::write_frame(s.dir / "b_1.npy", 1, 5);  // another size
  EXPECT_NE(sequence::refusal(s.dir / "b_{frame}.npy").message().find("one size"),
            std::string::npos);
  sequence::write_frame(s.dir / "c_7.npy", 7);
  sequence::write_frame(s.dir / "c_007.npy", 7);  // two files of one number
  EXPECT_NE(sequence::refusal(s.dir / "c_{frame}.npy").message().find("two files"),
            std::string::npos);
  std::ofstream(s.dir / "d_0.npy") << "not a numpy file";
  sequence::write_frame(s.dir / "d_1.npy", 1);
  EXPECT_NE(sequence::refusal(s.dir / "d_{frame}.npy").message().find("d_0.npy"),
            std::string::npos);
  EXPECT_NE(sequence::refusal(s.dir / "e_{frame}.npy").message().find("no file matches"),
            std::string::npos);
  EXPECT_FALSE(sequence::refusal(s.dir / "a_{frame:0}.npy").ok());
  EXPECT_FALSE(sequence::refusal(s.dir / "a_{frame.npy").ok());
  EXPECT_FALSE(sequence::refusal(s.dir / "a_{frame}_{frame}.npy").ok());
  EXPECT_FALSE(sequence::refusal(s.dir / "nofolder" / "a_{frame}.npy").ok());
  // Frames of different sizes handed to the library directly, and a bad frame rate.
  const auto map = [](int rows) {
    auto m = std::make_shared<HeightMap>();
    m->rows = rows, m->cols = 2, m->values.assign(static_cast<std::size_t>(2 * rows), 0.0f);
    return std::shared_ptr<const HeightMap>(m);
  };
  Waveform w{.frames = {map(2), map(3)}};
  EXPECT_FALSE(ocean::waves::validate(w).ok());
  w.frames = {map(2), map(2)};
  EXPECT_TRUE(ocean::waves::validate(w).ok());
  w.fps_hz = 0.0;
  EXPECT_FALSE(ocean::waves::validate(w).ok());
}

}  // namespace
