// Parsing and writing the userdata formats of formats.h.
#include "smachac/robot/formats.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

namespace smachac::robot {
namespace {

constexpr std::string_view kPoseShape =
    "[[x, y, z], [qx, qy, qz, qw]] or [x, y, z, qx, qy, qz, qw]";

[[noreturn]] void fail(std::string_view what, std::string_view expected, const rt::Value& got) {
  throw FormatError(std::string(what) + " must be " + std::string(expected) + ", not " +
                    got.repr());
}

// The numbers of a list of exactly `count` numbers, or nothing.
std::optional<std::vector<double>> numberList(const rt::Value& value, std::size_t count) {
  if (value.type() != rt::ValueType::List || value.list().size() != count) return std::nullopt;
  std::vector<double> result;
  for (const rt::Value& item : value.list()) {
    if (item.type() != rt::ValueType::Int && item.type() != rt::ValueType::Double) {
      return std::nullopt;
    }
    const double number = item.as<double>();
    if (!std::isfinite(number)) return std::nullopt;
    result.push_back(number);
  }
  return result;
}

// Position and quaternion numbers (x y z qx qy qz qw) of a pose in either shape.
std::optional<std::array<double, 7>> poseNumbers(const rt::Value& value) {
  std::array<double, 7> out{};
  if (auto flat = numberList(value, 7)) {
    std::copy(flat->begin(), flat->end(), out.begin());
    return out;
  }
  if (value.type() != rt::ValueType::List || value.list().size() != 2) return std::nullopt;
  auto position = numberList(value.list()[0], 3);
  auto rotation = numberList(value.list()[1], 4);
  if (!position || !rotation) return std::nullopt;
  std::copy(position->begin(), position->end(), out.begin());
  std::copy(rotation->begin(), rotation->end(), out.begin() + 3);
  return out;
}

double norm(const sim::Quaternion& q) {
  return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
}

sim::Pose toPose(const std::array<double, 7>& n) {
  return {{n[0], n[1], n[2]}, {n[6], n[3], n[4], n[5]}};
}

sim::Quaternion unit(const sim::Quaternion& q) {
  const double length = norm(q);
  return {q.w / length, q.x / length, q.y / length, q.z / length};
}

sim::Quaternion multiply(const sim::Quaternion& a, const sim::Quaternion& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

}  // namespace

sim::Pose parsePose(const rt::Value& value) {
  const auto n = poseNumbers(value);
  if (!n) fail("a pose", kPoseShape, value);
  sim::Pose pose = toPose(*n);
  if (norm(pose.orientation) < 1e-6) fail("a pose's quaternion", "non-zero", value);
  pose.orientation = unit(pose.orientation);
  return pose;
}

sim::Pose parseOffset(const rt::Value& value) {
  if (auto position = numberList(value, 3))
    return {{(*position)[0], (*position)[1], (*position)[2]}};
  const auto n = poseNumbers(value);
  if (!n) fail("an offset", std::string(kPoseShape) + " or [x, y, z]", value);
  sim::Pose offset = toPose(*n);
  const bool no_rotation = norm(offset.orientation) < 1e-12;
  offset.orientation = no_rotation ? sim::Quaternion{} : unit(offset.orientation);
  return offset;
}

sim::Pose applyOffset(const sim::Pose& pose, const sim::Pose& offset) {
  const sim::Vec3 p{pose.position.x + offset.position.x, pose.position.y + offset.position.y,
                    pose.position.z + offset.position.z};
  return {p, unit(multiply(pose.orientation, offset.orientation))};
}

sim::JointPositions parseJointPositions(const rt::Value& value) {
  const rt::Value* joints = &value;
  if (value.type() == rt::ValueType::List && value.list().size() == 1) joints = &value.list()[0];
  const auto n = numberList(*joints, sim::kArmJointCount);
  if (!n) fail("joint positions", "a list of 7 numbers [s0, s1, e0, e1, w0, w1, w2]", value);
  sim::JointPositions result{};
  std::copy(n->begin(), n->end(), result.begin());
  return result;
}

std::vector<sim::JointPositions> parseJointPoints(const rt::Value& value) {
  if (value.type() != rt::ValueType::List || value.list().empty()) {
    fail("joint points", "a non-empty list of joint positions", value);
  }
  std::vector<sim::JointPositions> points;
  for (const rt::Value& point : value.list()) points.push_back(parseJointPositions(point));
  return points;
}

sim::Side parseLimb(std::string_view limb) {
  if (limb == "left") return sim::Side::Left;
  if (limb == "right") return sim::Side::Right;
  fail("a limb", "`left` or `right`", rt::Value(limb));
}

sim::Frame parseFrame(std::string_view frame) {
  if (frame.empty() || frame == "world") return sim::Frame::World;
  if (frame == "base") return sim::Frame::Base;
  fail("a reference frame", "`base` or `world`", rt::Value(frame));
}

rt::Value poseValue(const sim::Pose& pose) {
  const sim::Vec3& p = pose.position;
  const sim::Quaternion& q = pose.orientation;
  return rt::List{rt::List{p.x, p.y, p.z}, rt::List{q.x, q.y, q.z, q.w}};
}

rt::Value jointsValue(const sim::JointPositions& joints) {
  return rt::List(joints.begin(), joints.end());
}

}  // namespace smachac::robot
