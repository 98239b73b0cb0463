// The plant simulator: the default experiment, one bonl::plant::simulate call of the paper's
// multi-sine for 50 s with default parameters and options (CVODE, 1 kHz command grid, 100 Hz output,
// sensor noise). The counter `realtime_factor` is simulated seconds per wall second; `steps` is
// CVODE's internal step count per run.
//
// Name: plant/simulate/paper_multisine_50s.

#include <benchmark/benchmark.h>

#include <bonl/plant/excitation.hpp>
#include <bonl/plant/simulator.hpp>

namespace {

void plant_simulate(benchmark::State& state) {
  const bonl::plant::Parameters parameters{};
  const bonl::plant::Command command = bonl::plant::excitation::paper_multisine();
  const bonl::plant::SimulationOptions options;  // duration 50 s
  long steps = 0;
  for (auto _ : state) {
    bonl::plant::Trajectory run = bonl::plant::simulate(parameters, command, options);
    benchmark::DoNotOptimize(run.measured_angle.data());
    benchmark::ClobberMemory();
    steps = run.steps;
  }
  state.counters["realtime_factor"] =
      benchmark::Counter(options.duration, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["simulated_s"] = options.duration;
}

}  // namespace

BENCHMARK(plant_simulate)->Name("plant/simulate/paper_multisine_50s")->Unit(benchmark::kMillisecond)->UseRealTime();
