#pragma once
// The cores this process may run on: its CPU affinity mask (taskset, a container's cpuset), not
// the machine's count, which std::thread::hardware_concurrency gives. Defaults of thread counts and
// the benchmark's "cores" use it, so a run pinned to one core says one core.

namespace stoneskip {

// At least 1: the affinity mask's CPU count, or hardware_concurrency where the mask is unreadable.
int usable_cores();

}  // namespace stoneskip
