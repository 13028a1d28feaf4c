// bench_mujoco_peer: MuJoCo's mj_step on the exported characters (see mujoco_peer.hpp). Without
// MuJoCo the binary is empty (benchmark_main still links and runs, reporting nothing).
#include "mujoco_peer/mujoco_peer.hpp"
