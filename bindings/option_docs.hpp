#pragma once
// The documentation of the estimator's and identify's keyword options, written once. The docstrings of
// identify, Estimator and control.AdaptiveInverse take their entries from this table (option_docs), so
// that an option reads the same wherever it is taken; tests/python/test_option_docs.py checks that each
// entry's default is the one the signature has. The texts follow C++'s EstimatorOptions and
// IdentifyOptions (bonl/estimator/recursive_estimator.hpp, identify_options.hpp), with the defaults
// their resolved_* functions give, and the models' EstimatorSettings.

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

namespace bonl_python {

/// One entry of a numpy-style Parameters section.
struct OptionDoc {
  const char* name;
  const char* type;  ///< after "name : ", with the default where the signature has a value
  const char* text;  ///< the meaning; newlines start the entry's next line
};

inline constexpr OptionDoc kOptionDocs[] = {
    {"passes", "int, default 1", "Passes of the recursive estimator over the record(s) (the paper's step 5)."},
    {"method", "{'output_error', 'equation_error', 'paper'}, default 'output_error'",
     "The recursive estimator (docs/explanation/algorithm.md). 'output_error': recursive prediction-error\n"
     "method on the free-run simulation error. 'equation_error': internal variables from the measured\n"
     "output (ARX: least squares). 'paper': eqs. (21)-(31) as written."},
    {"forgetting", "float, tuple or 'adaptive', optional",
     "Forgetting factor: a constant in (0, 1], (initial, initial_samples, final), or 'adaptive' (the\n"
     "adaptive memory). Default: 'adaptive' for output_error, the paper's 0.98 for 200 samples then 1\n"
     "for the others."},
    {"p0", "float, optional", "P(0) = p0 I. Default: 10 for output_error, 1e6 for the others."},
    {"trace_ceiling", "float, optional",
     "trace(P) is kept at or below trace_ceiling * trace(P(0)) by reducing the forgetting where it\n"
     "would grow P beyond that (no covariance wind-up under poor excitation). >= 1; inf turns it off\n"
     "(the paper's algorithm exactly as written). Default: 10 for output_error, 1 for the others."},
    {"recover_after", "int, default 0",
     "After this many refused updates in a row, reset P to p0 I automatically (keeping theta);\n"
     "0: never (check ``diverged`` and call ``recover()``)."},
    {"stability_radius", "float, default 0.999",
     "output_error: the linear block's poles are kept inside this radius (updates shortened)."},
    {"window", "WindowRefinementOptions, optional",
     "output_error: the window refinement, Levenberg-Marquardt on the newest samples spread over the\n"
     "updates, from the output-error recursion's estimate and from an equation-error recursion's beside.\n"
     "None: the default (on); ``bonl.WindowRefinementOptions(enabled=False)``: the recursion alone."},
    {"refine_iterations", "int, default 100",
     "Levenberg-Marquardt iterations of the refinement that follows the recursive stage for\n"
     "'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the\n"
     "free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block\n"
     "stable."},
    {"normalise", "bool, default True",
     "Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same\n"
     "whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:\n"
     "the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,\n"
     "then the recursion runs over them and on in coordinates where the parameters are of order one.\n"
     "identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model\n"
     "returned in the data's units; the recursive estimate returned as it is ('paper',\n"
     "refine_iterations=0, ARX least squares) is the online estimator's."},
    {"operating_point", "{None, 'mean', 'initial'}, default None",
     "The identified model's operating point (u0, y0): None keeps the structure's\n"
     "(Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the\n"
     "first sample of the first record (the record starts at rest there)."},
    {"initialisation_window", "int, default 0",
     "Where identify refines: each record's free run starts after its first initialisation_window\n"
     "samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is\n"
     "scored after them, instead of from rest: the model is fitted the way a test protocol with that\n"
     "state-initialisation window uses it (records that do not start at rest; an integrating plant,\n"
     "whose position keeps any transient of the start). Shorter than every record."},
    // The model's own settings (its EstimatorSettings, bindings/model_settings.hpp): PseudoHammersteinWiener's.
    {"c0", "float, optional",
     "PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of\n"
     "equation_error and paper, in the output's units, or where the estimator normalises a fraction of\n"
     "the output's scale (output_error starts at 0). Default: 0.01."},
    {"backlash_hold", "int, optional",
     "PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many\n"
     "samples after each start from rest. Default: 200."},
};

/// The numpy-style Parameters entries of the named options of kOptionDocs, in the order given: "name :
/// type" and the text indented by four spaces. std::logic_error for a name the table lacks.
inline std::string option_docs(std::initializer_list<std::string_view> names) {
  std::string out;
  for (const std::string_view name : names) {
    const OptionDoc* found = nullptr;
    for (const OptionDoc& doc : kOptionDocs) {
      if (name == doc.name) found = &doc;
    }
    if (!found) throw std::logic_error("bonl: option_docs: no entry for " + std::string(name));
    out += std::string(found->name) + " : " + found->type + "\n    ";
    for (const char* c = found->text; *c != '\0'; ++c) out += *c == '\n' ? std::string("\n    ") : std::string(1, *c);
    out += "\n";
  }
  return out;
}

}  // namespace bonl_python
