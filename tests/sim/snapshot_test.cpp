// Snapshots: a headless OSMesa render of the scene written as PNG, read back, checked for
// size and for an image that is not one flat colour.
#include <doctest/doctest.h>
#include <png.h>

#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "sim_test_support.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/snapshot.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::sim::test {
namespace {

// Reads a PNG as RGB; returns false when it cannot.
bool readPng(const std::string& path, Image& image) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, path.c_str()) == 0) return false;
  png.format = PNG_FORMAT_RGB;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  return png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr) != 0;
}

size_t distinctColours(const Image& image) {
  std::set<unsigned> colours;
  for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    colours.insert(image.rgb[i] << 16 | image.rgb[i + 1] << 8 | image.rgb[i + 2]);
  }
  return colours.size();
}

TEST_SUITE("sim_snapshot") {
  TEST_CASE("a snapshot is written as a PNG of the requested size with a real picture") {
    auto world = loadWorld();
    putBlockOnTable(*world, "block1", kPose1);
    world->limb(Side::Left).moveToJointPositions(untuckPose(Side::Left), {.speed = 1.0});
    Snapshotter snapshotter(*world);
    const std::string path = "sim_snapshot_test.png";
    const SnapshotResult written = snapshotter.writePng(path, {.width = 320, .height = 240});
    INFO(written.error);
    REQUIRE(written.ok);
    Image image;
    REQUIRE(readPng(path, image));
    CHECK(image.width == 320);
    CHECK(image.height == 240);
    CHECK(distinctColours(image) > 50);

    const SnapshotResult fixed = snapshotter.writePng(path, {.camera = "overview"});
    CHECK(fixed.ok);
    REQUIRE(readPng(path, image));
    CHECK(image.width == 640);
    CHECK(distinctColours(image) > 50);
    std::remove(path.c_str());
  }

  TEST_CASE("bad snapshot requests are error results") {
    auto world = loadWorld();
    Snapshotter snapshotter(*world);
    Image image;
    std::string error;
    CHECK_FALSE(snapshotter.capture({.width = 5000, .height = 10}, image, error));
    CHECK_FALSE(error.empty());
    CHECK_FALSE(snapshotter.writePng("out.png", {.camera = "no_such_camera"}).ok);
    CHECK_FALSE(snapshotter.writePng("/nonexistent/dir/out.png").ok);
  }
}

}  // namespace
}  // namespace smachac::sim::test
