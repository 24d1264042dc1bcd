/**
 * @file module.cpp  The extension `eomgen._eomgen`: the generator's stages and the simulation driver as a few
 * functions over plain values (strings, dicts, NumPy arrays), which eomgen/__init__.py turns into the Python API
 * (docs/python.md); the functions are in the bind_*.cpp files (binding.hpp), the exceptions and the module here.
 */
#include "binding.hpp"

#include "checker/checker.hpp"
#include "cli/process.hpp"
#include "eomgen/errors.hpp"
#include "mechanics/small_oscillations.hpp"
#include "model/families.hpp"

namespace py = pybind11;

namespace eomgen::python {

Exceptions& exceptions() {
    static Exceptions* e = new Exceptions();  // never destroyed: Python owns the classes until it exits
    return *e;
}

namespace {

void raise(const py::object& type, const char* what) { PyErr_SetString(type.ptr(), what); }

}  // namespace
}  // namespace eomgen::python

PYBIND11_MODULE(_eomgen, m) {
    using namespace eomgen::python;
    m.doc() = "eomgen's generator and simulation driver; use the package `eomgen`, not this module";

    Exceptions& e = exceptions();
    e.error = py::reinterpret_steal<py::object>(
        PyErr_NewExceptionWithDoc("eomgen.Error", "Any error of eomgen.", PyExc_Exception, nullptr));
    auto sub = [&e](const char* name, const char* doc, PyObject* also) {
        py::tuple bases = also ? py::make_tuple(e.error, py::handle(also)) : py::make_tuple(e.error);
        return py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(name, doc, bases.ptr(), nullptr));
    };
    e.model = sub("eomgen.ModelError", "A model file is wrong; the message starts with file:line:col.", PyExc_ValueError);
    e.usage = sub("eomgen.UsageError", "A bad option or value (an unknown parameter, a method without dt, ...).",
                  PyExc_ValueError);
    e.simulation = sub("eomgen.SimulationError", "An integration failed (a singular mass matrix, a blown-up state, "
                                                 "the step limit).", nullptr);
    e.compile = sub("eomgen.CompileError", "The C++ compiler is missing or failed; the message names its log.", nullptr);
    e.cache = sub("eomgen.CacheError", "The cache of compiled models cannot be used safely.", PyExc_OSError);
    e.check = sub("eomgen.CheckError", "A --section or map entry of a check cannot be used.", PyExc_ValueError);
    m.attr("Error") = e.error;
    m.attr("ModelError") = e.model;
    m.attr("UsageError") = e.usage;
    m.attr("SimulationError") = e.simulation;
    m.attr("CompileError") = e.compile;
    m.attr("CacheError") = e.cache;
    m.attr("CheckError") = e.check;
    py::register_exception_translator([](std::exception_ptr p) {
        if (!p) return;
        Exceptions& x = exceptions();
        try {
            std::rethrow_exception(p);
        } catch (const eomgen::ModelError& err) {
            raise(x.model, err.what());
        } catch (const eomgen::sim::UsageError& err) {
            raise(x.usage, err.what());
        } catch (const eomgen::InconsistentInitialConditions& err) {
            const std::string what = std::string(err.what()) +
                                     " (give a state on the constraints with init=, or project_initial=True)";
            raise(x.simulation, what.c_str());
        } catch (const eomgen::SimulationError& err) {
            raise(x.simulation, err.what());
        } catch (const eomgen::cli::CompileError& err) {
            const std::string what = std::string(err.what()) + "\n  command: " + err.command + "\n  log: " + err.log;
            raise(x.compile, what.c_str());
        } catch (const eomgen::cli::CacheError& err) {
            raise(x.cache, err.what());
        } catch (const eomgen::cli::TempDirError& err) {
            raise(x.cache, err.what());
        } catch (const eomgen::checker::CheckError& err) {
            raise(x.check, err.what());
        }
    });

    py::class_<LoadedModel>(m, "LoadedModel")
        .def(py::init<std::string, std::string, std::string>(), py::arg("text"), py::arg("path"), py::arg("name"))
        .def("describe", &describe)
        .def("equations", &equations)
        .def("show", &show)
        .def("latex", &latex)
        .def("simulate", &simulate, py::arg("t_end"), py::arg("method"), py::arg("rtol"), py::arg("atol"),
             py::arg("dt"), py::arg("samples"), py::arg("max_steps"), py::arg("set"), py::arg("init"),
             py::arg("until"), py::arg("project_initial"), py::arg("switch_events"), py::arg("sensitivities"),
             py::arg("state_error_only"), py::arg("use_cache"), py::arg("interpret"))
        .def("sweep", &sweep, py::arg("names"), py::arg("values"), py::arg("t_end"), py::arg("method"), py::arg("rtol"),
             py::arg("atol"), py::arg("dt"), py::arg("max_steps"), py::arg("set"), py::arg("init"), py::arg("until"),
             py::arg("project_initial"), py::arg("switch_events"), py::arg("threads"), py::arg("use_cache"), py::arg("interpret"))
        .def("rhs", &rhs, py::arg("t"), py::arg("x"), py::arg("set"), py::arg("use_cache"), py::arg("interpret"))
        .def("modes", &modes, py::arg("set"), py::arg("at"), py::arg("momentum"), py::arg("inputs"))
        .def("jacobian", &jacobian, py::arg("t"), py::arg("x"), py::arg("set"), py::arg("use_cache"), py::arg("interpret"))
        .def("shared_object", &LoadedModel::shared_object, py::arg("use_cache"))
        .def("check", &check, py::arg("text"), py::arg("path"), py::arg("sections"), py::arg("set"));
    m.def("read_file", [](const std::string& path) { return py::bytes(eomgen::read_model_file(path)); },
          "The bytes of a model file (ModelError when unreadable).");
    m.def("family_text", [](const std::string& spec) {
        try {
            return eomgen::family_model_text(eomgen::parse_family_spec(spec));
        } catch (const std::invalid_argument& e) {
            throw eomgen::sim::UsageError(std::string("family: ") + e.what());
        }
    }, "The model file of an n-link family, e.g. \"pendulum:n=8\" (eomgen generate --family).");
    m.def("cache_directory", [] { return eomgen::cli::cache_directory().string(); });
}
