// A C interface to the MuJoCo Baxter (smachac_sim) for other languages: the ROS node of
// sim/ros loads it with Python's ctypes. One handle owns one world; calls on a handle must not
// overlap (the node serialises them). Poses are in Baxter's base frame unless a frame is
// given, as [x, y, z, qx, qy, qz, qw] (ROS order); joint arrays are [s0 s1 e0 e1 w0 w1 w2];
// `side` is 0 for left, 1 for right. Nothing here throws or aborts: failures are return values.
#pragma once

#ifdef __cplusplus
extern "C" {
#endif

typedef struct SmachacSimWorld SmachacSimWorld;

/// Loads the scene (NULL or "": the default one), arms at q = 0 holding still. NULL on
/// failure, with the reason in `error` (at most error_size bytes, NUL-terminated).
SmachacSimWorld* smachac_sim_open(const char* scene_path, char* error, int error_size);
void smachac_sim_close(SmachacSimWorld* world);

/// Steps the physics `count` times; returns the simulated time (s).
double smachac_sim_step(SmachacSimWorld* world, int count);
double smachac_sim_time(const SmachacSimWorld* world);
double smachac_sim_timestep(const SmachacSimWorld* world);

/// Joint names of one arm ("left_s0" ...), written into names[7] (pointers valid as long as
/// the world).
void smachac_sim_joint_names(const SmachacSimWorld* world, int side, const char* names[7]);
/// Positions (rad), velocities (rad/s) and efforts (N m: servo and gravity compensation) of
/// one arm.
void smachac_sim_joint_state(const SmachacSimWorld* world, int side, double position[7],
                             double velocity[7], double effort[7]);
/// Baxter's joint position mode: the arm approaches `goal` at `speed` times the joint velocity
/// limits and holds it. Returns 0 (and does nothing) for a goal outside the joint limits.
int smachac_sim_command_positions(SmachacSimWorld* world, int side, const double goal[7],
                                  double speed);
/// The endpoint (TCP) pose and its twist [vx vy vz wx wy wz] in the base frame.
void smachac_sim_endpoint(const SmachacSimWorld* world, int side, double pose[7], double twist[6]);
/// Joint positions that put the endpoint at `pose`, seeded from the arm's current positions.
/// Returns 1 when solved, 0 when out of reach or invalid (joints then hold the best attempt).
int smachac_sim_solve_ik(SmachacSimWorld* world, int side, const double pose[7], double joints[7]);

/// Commands the gripper's fingers to `percent` of their travel (0 closed, 100 open).
void smachac_sim_gripper_command(SmachacSimWorld* world, int side, double percent);
/// Where the fingers are (percent open), whether they move, whether they hold a body
/// between both pads and have stopped, and the finger force (percent of the maximum).
void smachac_sim_gripper_state(const SmachacSimWorld* world, int side, double* percent, int* moving,
                               int* gripping, double* force);

/// Places body `name` (a block's centre, the table's frame) at `pose`, given in the base frame
/// (frame 0) or the world frame (frame 1), at rest. Returns 0 placed, 1 no such body, 2 not
/// movable, 3 invalid pose.
int smachac_sim_place_body(SmachacSimWorld* world, const char* name, const double pose[7],
                           int frame);
/// The body's pose in the base frame; returns 0 for an unknown body.
int smachac_sim_body_pose(const SmachacSimWorld* world, const char* name, double pose[7]);

/// The scene report as a Baxter program prints it (time, blocks, stack verdict, warnings);
/// returns its length, writing at most size - 1 bytes and a NUL.
int smachac_sim_report(const SmachacSimWorld* world, char* text, int size);
/// Writes a PNG snapshot; returns 1, or 0 with the reason in `error`.
int smachac_sim_snapshot(SmachacSimWorld* world, const char* path, char* error, int error_size);

#ifdef __cplusplus
}
#endif
