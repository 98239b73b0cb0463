// SteppingPlant: the integration core (integrator.hpp) behind a one-sample-per-call interface.

#include "bonl/plant/stepping_plant.hpp"

#include <stdexcept>
#include <utility>

#include "bonl/detail/validate.hpp"
#include "integrator.hpp"

namespace bonl::plant {

namespace {
constexpr const char* kWhere = "SteppingPlant";
}

SteppingPlant::SteppingPlant(const Parameters& parameters, const SimulationOptions& options)
    : m_parameters(parameters), m_options(options) {
  m_parameters.validate();
  detail::validate_options(m_options, m_parameters, kWhere, false);
  m_integrator = std::make_unique<detail::Integrator>(m_parameters, m_options, kWhere);
}

SteppingPlant::SteppingPlant(SteppingPlant&&) noexcept = default;
SteppingPlant& SteppingPlant::operator=(SteppingPlant&&) noexcept = default;
SteppingPlant::~SteppingPlant() = default;

const detail::Integrator& SteppingPlant::integrator() const {
  if (!m_integrator) throw std::logic_error("bonl: SteppingPlant: used after it was moved from");
  return *m_integrator;
}

Measurement SteppingPlant::step(double command) {
  integrator();
  bonl::detail::require_finite(command, std::string(kWhere) + ": command");
  m_integrator->advance([command](double) { return command; });
  return m_integrator->measurement();
}

Measurement SteppingPlant::reset() {
  integrator();
  // A new integrator, built before the old one goes: CVODE from scratch, the noise from its seed.
  m_integrator = std::make_unique<detail::Integrator>(m_parameters, m_options, kWhere);
  return m_integrator->measurement();
}

Measurement SteppingPlant::reset(double initial_position, std::uint64_t noise_seed) {
  integrator();
  SimulationOptions options = m_options;
  options.initial_position = initial_position;
  options.noise_seed = noise_seed;
  detail::validate_options(options, m_parameters, kWhere, false);
  m_integrator = std::make_unique<detail::Integrator>(m_parameters, options, kWhere);
  m_options = std::move(options);
  return m_integrator->measurement();
}

void SteppingPlant::set_parameters(const Parameters& parameters) {
  integrator();
  parameters.validate();
  const struct {
    const char* name;
    double Parameters::*member;
  } geometry[] = {{"stroke", &Parameters::stroke},
                  {"pivot_to_rod_pin", &Parameters::pivot_to_rod_pin},
                  {"pivot_to_base_pin", &Parameters::pivot_to_base_pin},
                  {"retracted_length", &Parameters::retracted_length}};
  for (const auto& g : geometry) {
    if (parameters.*(g.member) != m_parameters.*(g.member))
      bonl::detail::fail(std::string(kWhere) + ": set_parameters: " + g.name +
                         " cannot change while the plant runs (the linkage maps the position to the angle), was " +
                         bonl::detail::format_number(m_parameters.*(g.member)) + ", got " +
                         bonl::detail::format_number(parameters.*(g.member)));
  }
  m_integrator->set_parameters(parameters);
  m_parameters = parameters;
}

const Measurement& SteppingPlant::measurement() const { return integrator().measurement(); }
double SteppingPlant::time() const { return integrator().measurement().time; }
long SteppingPlant::steps() const { return integrator().steps(); }

}  // namespace bonl::plant
