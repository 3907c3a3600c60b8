// Headless PNG snapshots of the world through OSMesa (software OpenGL, no display or GPU).
// Nothing is rendered unless a Snapshotter is created and asked for a frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "smachac/sim/types.h"

namespace smachac::sim {

class World;

/// A free camera looking at `lookat` (world frame, m) from `distance` (m); angles in degrees.
struct CameraView {
  Vec3 lookat{0.75, 0.0, 0.85};
  double distance = 2.2;
  double azimuth = 200.0;
  double elevation = -30.0;
};

struct SnapshotOptions {
  int width = 640;       ///< at most the model's offwidth (1280)
  int height = 480;      ///< at most the model's offheight (960)
  std::string camera{};  ///< a camera named in the model ("overview"); empty: use `view`
  CameraView view{};
};

/// An RGB image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
};

struct SnapshotResult {
  bool ok = false;
  std::string error;
};

class Snapshotter {
 public:
  explicit Snapshotter(World& world);
  Snapshotter(const Snapshotter&) = delete;
  Snapshotter& operator=(const Snapshotter&) = delete;
  ~Snapshotter();

  /// Renders the current state. On failure `error` says why and the image is empty.
  bool capture(const SnapshotOptions& options, Image& image, std::string& error);
  /// capture() then write a PNG file.
  SnapshotResult writePng(const std::string& path, const SnapshotOptions& options = {});

 private:
  struct Renderer;
  World& world_;
  std::unique_ptr<Renderer> renderer_;
};

/// Writes an RGB image (rows top to bottom) as PNG; returns an error message or "".
std::string writePngFile(const std::string& path, const Image& image);

}  // namespace smachac::sim
