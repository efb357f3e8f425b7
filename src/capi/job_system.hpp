// src/capi/job_system.hpp — an engine's ocean_job_system as a TaskRunner (private to src/capi).
#pragma once

#include <memory>
#include <string_view>

#include "ocean/core.hpp"
#include "ocean/ocean.h"
#include "ocean/task_runner.hpp"

namespace ocean::capi {

/// invalid_argument naming the field ("<function>: job_system->parallel_for is NULL") unless the
/// table is usable: struct_size large enough, parallel_for set, start_job and wait_job both or
/// neither, concurrency in [1, kMaxRunnerThreads].
Status validate_job_system(const ocean_job_system& jobs, std::string_view function);

/// A TaskRunner that runs its loops and its async slot's jobs on `jobs` (copied; its user_data
/// must stay valid as long as the runner). Precondition: validate_job_system(jobs) is ok.
std::shared_ptr<TaskRunner> make_job_system_runner(const ocean_job_system& jobs);

}  // namespace ocean::capi
