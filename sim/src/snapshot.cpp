// Snapshotter: MuJoCo's renderer in an OSMesa (software) context, read back as RGB.
#include "smachac/sim/snapshot.h"

#include <GL/osmesa.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <memory>

#include "smachac/sim/world.h"

namespace smachac::sim {

/// One OSMesa context with MuJoCo's scene and GPU-side context; created on first use.
struct Snapshotter::Renderer {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> framebuffer;  // OSMesa's default framebuffer (RGBA)
  int width = 0;
  int height = 0;
  mjvScene scene{};
  mjvOption option{};
  mjrContext gl{};

  ~Renderer() {
    if (context == nullptr) return;
    makeCurrent();
    mjr_freeContext(&gl);
    mjv_freeScene(&scene);
    OSMesaDestroyContext(context);
  }

  bool makeCurrent() {
    return OSMesaMakeCurrent(context, framebuffer.data(), GL_UNSIGNED_BYTE, width, height) != 0;
  }

  bool create(const mjModel* model, std::string& error) {
    width = model->vis.global.offwidth;
    height = model->vis.global.offheight;
    context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (context == nullptr) {
      error = "cannot create an OSMesa context";
      return false;
    }
    framebuffer.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * 4, 0);
    if (!makeCurrent()) {
      error = "cannot make the OSMesa context current";
      return false;
    }
    mjv_defaultScene(&scene);
    mjv_makeScene(model, &scene, 2000);
    mjv_defaultOption(&option);
    mjr_defaultContext(&gl);
    mjr_makeContext(model, &gl, mjFONTSCALE_100);
    mjr_setBuffer(mjFB_OFFSCREEN, &gl);
    return true;
  }
};

namespace {

std::string makeCamera(const mjModel* model, const SnapshotOptions& options, mjvCamera& camera) {
  mjv_defaultCamera(&camera);
  if (!options.camera.empty()) {
    camera.type = mjCAMERA_FIXED;
    camera.fixedcamid = mj_name2id(model, mjOBJ_CAMERA, options.camera.c_str());
    return camera.fixedcamid < 0 ? "model has no camera `" + options.camera + "`" : "";
  }
  camera.type = mjCAMERA_FREE;
  camera.lookat[0] = options.view.lookat.x;
  camera.lookat[1] = options.view.lookat.y;
  camera.lookat[2] = options.view.lookat.z;
  camera.distance = options.view.distance;
  camera.azimuth = options.view.azimuth;
  camera.elevation = options.view.elevation;
  return "";
}

// MuJoCo reads pixels bottom row first; images are top row first.
void flipRows(Image& image) {
  const size_t stride = static_cast<size_t>(image.width) * 3;
  for (int top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom) {
    std::swap_ranges(image.rgb.begin() + static_cast<std::ptrdiff_t>(stride * top),
                     image.rgb.begin() + static_cast<std::ptrdiff_t>(stride * (top + 1)),
                     image.rgb.begin() + static_cast<std::ptrdiff_t>(stride * bottom));
  }
}

}  // namespace

Snapshotter::Snapshotter(World& world) : world_(world) {}

Snapshotter::~Snapshotter() = default;

bool Snapshotter::capture(const SnapshotOptions& options, Image& image, std::string& error) {
  image = {};
  const mjModel* model = world_.model();
  if (options.width <= 0 || options.height <= 0 || options.width > model->vis.global.offwidth ||
      options.height > model->vis.global.offheight) {
    error = "snapshot size must be within the model's offscreen buffer";
    return false;
  }
  if (!renderer_) {
    auto renderer = std::make_unique<Renderer>();
    if (!renderer->create(model, error)) return false;
    renderer_ = std::move(renderer);
  }
  mjvCamera camera;
  error = makeCamera(model, options, camera);
  if (!error.empty() || !renderer_->makeCurrent()) {
    if (error.empty()) error = "cannot make the OSMesa context current";
    return false;
  }
  const mjrRect viewport = {0, 0, options.width, options.height};
  {
    auto guard = world_.lock();
    mjv_updateScene(model, world_.data(), &renderer_->option, nullptr, &camera, mjCAT_ALL,
                    &renderer_->scene);
  }
  mjr_setBuffer(mjFB_OFFSCREEN, &renderer_->gl);
  mjr_render(viewport, &renderer_->scene, &renderer_->gl);
  image.width = options.width;
  image.height = options.height;
  image.rgb.assign(static_cast<size_t>(options.width) * static_cast<size_t>(options.height) * 3, 0);
  mjr_readPixels(image.rgb.data(), nullptr, viewport, &renderer_->gl);
  flipRows(image);
  return true;
}

SnapshotResult Snapshotter::writePng(const std::string& path, const SnapshotOptions& options) {
  Image image;
  SnapshotResult result;
  if (!capture(options, image, result.error)) return result;
  result.error = writePngFile(path, image);
  result.ok = result.error.empty();
  return result;
}

}  // namespace smachac::sim
