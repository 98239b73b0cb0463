// The four models in Python: bonl.ARX, Hammerstein, HammersteinWiener, PseudoHammersteinWiener.
// They are the run-time-order C++ models; parameters follow the conventions of the README.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <bonl/io/model_json.hpp>
#include <bonl/models.hpp>

#include "bindings.hpp"
#include "conversions.hpp"

namespace bonl_python {
namespace {

const char* kSimulateDoc = R"doc(Free-run simulation from rest.

Parameters
----------
u : array_like, shape (n,)
    Input sequence.

Returns
-------
numpy.ndarray, shape (n,)
    The model's output, driven by u alone (past inputs and outputs are zero).

Raises
------
ValueError
    If u is not a finite 1-D array.
bonl.NumericalError
    If the simulation leaves the finite numbers (an unstable model).)doc";

const char* kPredictDoc = R"doc(One-step-ahead prediction from measured data.

Parameters
----------
u : array_like, shape (n,)
    Input sequence.
y : array_like, shape (n,)
    Measured output; y[k] is used to predict y[k + 1].

Returns
-------
numpy.ndarray, shape (n,)
    The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
    measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
    backlash memory is the measured y[k - 1]).)doc";

/// Methods every model shares.
template <class Model>
void bind_common(py::class_<Model>& cls) {
  cls.def(
         "simulate",
         [](const Model& model, const py::object& u) {
           const Eigen::VectorXd input = to_vector(u, "u");
           py::gil_scoped_release release;
           return Eigen::VectorXd(model.simulate(input));
         },
         py::arg("u"), kSimulateDoc)
      .def(
          "predict",
          [](const Model& model, const py::object& u, const py::object& y) {
            const Eigen::VectorXd input = to_vector(u, "u");
            const Eigen::VectorXd output = to_vector(y, "y");
            py::gil_scoped_release release;
            return Eigen::VectorXd(model.predict(input, output));
          },
          py::arg("u"), py::arg("y"), kPredictDoc)
      .def_property(
          "theta", [](const Model& model) { return Eigen::VectorXd(model.theta()); },
          [](Model& model, const py::object& theta) { model.set_theta(to_vector(theta, "theta")); },
          "numpy.ndarray: the parameter vector in the order of eq. (19).")
      .def_property_readonly("num_params", &Model::num_params, "int: number of identified parameters.")
      .def_property_readonly("na", &Model::na, "int: poles of the linear block.")
      .def_property_readonly("nb", &Model::nb, "int: B has nb + 1 coefficients b_0..b_nb.")
      .def_property_readonly("nk", &Model::nk, "int: pure delay in samples.")
      .def(
          "to_json", [](const Model& model, int indent) { return bonl::io::to_json(model, indent); },
          py::arg("indent") = -1,
          "str: the model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).")
      .def(py::pickle([](const Model& model) { return bonl::io::to_json(model); },
                      [](const std::string& text) { return bonl::io::model_from_json<Model>(text); }))
      .def("__copy__", [](const Model& model) { return Model(model); })
      .def("__deepcopy__", [](const Model& model, const py::dict&) { return Model(model); }, py::arg("memo"));
}

template <class Model>
void bind_front(py::class_<Model>& cls) {
  cls.def_property_readonly("r", &Model::r, "int: degree of the input polynomials.");
}

py::dict front_params(const Eigen::VectorXd& f, const Eigen::VectorXd& p, const Eigen::VectorXd& b,
                      const Eigen::VectorXd& a) {
  py::dict params;
  params["f"] = f;
  params["p"] = p;
  params["b"] = b;
  params["a"] = a;
  return params;
}

}  // namespace

void bind_models(py::module_& m) {
  py::register_exception<bonl::NumericalError>(m, "NumericalError", PyExc_ArithmeticError);

  py::class_<bonl::ARXd> arx(m, "ARX", R"doc(ARX model y(k) = -sum a_j y(k-j) + sum_{i=0..nb} b_i u(k-nk-i).

Parameters
----------
na, nb, nk : int
    Orders: na >= 1 poles, nb >= 0 (b has nb + 1 entries), delay nk >= 0.
b : array_like, optional
    b_0..b_nb (b_0 is free for ARX).
a : array_like, optional
    a_1..a_na.
)doc");
  arx.def(py::init([](Eigen::Index na, Eigen::Index nb, Eigen::Index nk, const py::object& b, const py::object& a) {
            bonl::ARXd model(na, nb, nk);
            if (!b.is_none()) model.set_b(to_vector(b, "b"));
            if (!a.is_none()) model.set_a(to_vector(a, "a"));
            return model;
          }),
          py::arg("na"), py::arg("nb"), py::arg("nk"), py::kw_only(), py::arg("b") = py::none(),
          py::arg("a") = py::none())
      .def_property_readonly(
          "params",
          [](const bonl::ARXd& model) {
            py::dict params;
            params["b"] = Eigen::VectorXd(model.b());
            params["a"] = Eigen::VectorXd(model.a());
            return params;
          },
          "dict: {'b': b_0..b_nb, 'a': a_1..a_na} as numpy arrays.")
      .def("__repr__", [](const bonl::ARXd& model) {
        return "ARX(na=" + std::to_string(model.na()) + ", nb=" + std::to_string(model.nb()) +
               ", nk=" + std::to_string(model.nk()) + ")";
      });
  bind_common(arx);

  py::class_<bonl::Hammersteind> hammerstein(m, "Hammerstein", R"doc(Hammerstein model: two-segment input polynomial, then the linear block (b_0 = 1).

w = sum_l f_l u^l + h(u) sum_l p_l u^l (h(u) = 1 for u < 0), x(k) = -sum a_j x(k-j) + sum b_i w(k-nk-i), y = x.

Parameters
----------
na, nb, nk, r : int
    Orders; r >= 1 is the polynomials' degree.
f, p : array_like, optional
    f_0..f_r and p_0..p_r (p_l = g_l - f_l, the change for u < 0).
b : array_like, optional
    b_0..b_nb with b_0 = 1.
a : array_like, optional
    a_1..a_na.
)doc");
  hammerstein
      .def(py::init([](Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, const py::object& f,
                       const py::object& p, const py::object& b, const py::object& a) {
             bonl::Hammersteind model(na, nb, nk, r);
             if (!f.is_none()) model.set_f(to_vector(f, "f"));
             if (!p.is_none()) model.set_p(to_vector(p, "p"));
             if (!b.is_none()) model.set_b(to_vector(b, "b"));
             if (!a.is_none()) model.set_a(to_vector(a, "a"));
             return model;
           }),
           py::arg("na"), py::arg("nb"), py::arg("nk"), py::arg("r"), py::kw_only(), py::arg("f") = py::none(),
           py::arg("p") = py::none(), py::arg("b") = py::none(), py::arg("a") = py::none())
      .def_property_readonly(
          "params",
          [](const bonl::Hammersteind& model) { return front_params(model.f(), model.p(), model.b(), model.a()); },
          "dict: {'f', 'p', 'b', 'a'} as numpy arrays.")
      .def("__repr__", [](const bonl::Hammersteind& model) {
        return "Hammerstein(na=" + std::to_string(model.na()) + ", nb=" + std::to_string(model.nb()) +
               ", nk=" + std::to_string(model.nk()) + ", r=" + std::to_string(model.r()) + ")";
      });
  bind_common(hammerstein);
  bind_front(hammerstein);

  py::class_<bonl::HammersteinWienerd> hw(m, "HammersteinWiener", R"doc(Hammerstein-Wiener model: the Hammerstein model followed by y = sum_{m=1..r1} q_m x^m (q_1 = 1).

Parameters
----------
na, nb, nk, r, r1 : int
    Orders; r1 >= 2 is the output polynomial's degree.
f, p, b, a : array_like, optional
    As for Hammerstein.
q : array_like, optional
    q_1..q_r1 with q_1 = 1.
)doc");
  hw.def(py::init([](Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index r1,
                     const py::object& f, const py::object& p, const py::object& b, const py::object& a,
                     const py::object& q) {
           bonl::HammersteinWienerd model(na, nb, nk, r, r1);
           if (!f.is_none()) model.set_f(to_vector(f, "f"));
           if (!p.is_none()) model.set_p(to_vector(p, "p"));
           if (!b.is_none()) model.set_b(to_vector(b, "b"));
           if (!a.is_none()) model.set_a(to_vector(a, "a"));
           if (!q.is_none()) model.set_q(to_vector(q, "q"));
           return model;
         }),
         py::arg("na"), py::arg("nb"), py::arg("nk"), py::arg("r"), py::arg("r1"), py::kw_only(),
         py::arg("f") = py::none(), py::arg("p") = py::none(), py::arg("b") = py::none(), py::arg("a") = py::none(),
         py::arg("q") = py::none())
      .def_property_readonly("r1", &bonl::HammersteinWienerd::r1, "int: degree of the output polynomial.")
      .def_property_readonly(
          "params",
          [](const bonl::HammersteinWienerd& model) {
            py::dict params = front_params(model.f(), model.p(), model.b(), model.a());
            params["q"] = Eigen::VectorXd(model.q());
            return params;
          },
          "dict: {'f', 'p', 'b', 'a', 'q'} as numpy arrays.")
      .def("__repr__", [](const bonl::HammersteinWienerd& model) {
        return "HammersteinWiener(na=" + std::to_string(model.na()) + ", nb=" + std::to_string(model.nb()) +
               ", nk=" + std::to_string(model.nk()) + ", r=" + std::to_string(model.r()) +
               ", r1=" + std::to_string(model.r1()) + ")";
      });
  bind_common(hw);
  bind_front(hw);

  py::class_<bonl::PseudoHammersteinWienerd> phw(m, "PseudoHammersteinWiener", R"doc(Pseudo-Hammerstein-Wiener model: the Hammerstein model followed by a symmetric, unit-slope backlash of half-width c.

y(k) = x(k) - c if x(k) > y(k-1) + c; x(k) + c if x(k) < y(k-1) - c; else y(k-1).

Parameters
----------
na, nb, nk, r : int
    Orders, as for Hammerstein.
f, p, b, a : array_like, optional
    As for Hammerstein.
c : float, optional
    Backlash half-width, c >= 0.
)doc");
  phw.def(py::init([](Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, const py::object& f,
                      const py::object& p, const py::object& b, const py::object& a, const py::object& c) {
            bonl::PseudoHammersteinWienerd model(na, nb, nk, r);
            if (!f.is_none()) model.set_f(to_vector(f, "f"));
            if (!p.is_none()) model.set_p(to_vector(p, "p"));
            if (!b.is_none()) model.set_b(to_vector(b, "b"));
            if (!a.is_none()) model.set_a(to_vector(a, "a"));
            if (!c.is_none()) model.set_c(to_scalar(c, "c"));
            return model;
          }),
          py::arg("na"), py::arg("nb"), py::arg("nk"), py::arg("r"), py::kw_only(), py::arg("f") = py::none(),
          py::arg("p") = py::none(), py::arg("b") = py::none(), py::arg("a") = py::none(), py::arg("c") = py::none())
      .def_property_readonly("c", &bonl::PseudoHammersteinWienerd::c, "float: backlash half-width.")
      .def_property_readonly(
          "params",
          [](const bonl::PseudoHammersteinWienerd& model) {
            py::dict params = front_params(model.f(), model.p(), model.b(), model.a());
            params["c"] = model.c();
            return params;
          },
          "dict: {'f', 'p', 'b', 'a'} as numpy arrays and 'c' as a float.")
      .def("__repr__", [](const bonl::PseudoHammersteinWienerd& model) {
        return "PseudoHammersteinWiener(na=" + std::to_string(model.na()) + ", nb=" + std::to_string(model.nb()) +
               ", nk=" + std::to_string(model.nk()) + ", r=" + std::to_string(model.r()) + ")";
      });
  bind_common(phw);
  bind_front(phw);
}

}  // namespace bonl_python
