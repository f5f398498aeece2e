#pragma once
/// @file CApiBoundary.hpp
/// The C boundary of the MoorDyn-compatible API: the registry that owns every open system (a MoorDyn
/// handle is the address of one), the conversion of handles, and the guards that run a function's body
/// and turn any exception into a MOORDYN_* code with the message on stderr (or the system's log):
///
/// | exception                  | code                        |
/// | -------------------------- | --------------------------- |
/// | capi::InvalidValue         | MOORDYN_INVALID_VALUE       |
/// | capi::NotImplemented       | MOORDYN_NON_IMPLEMENTED     |
/// | InputError                 | MOORDYN_INVALID_INPUT       |
/// | ConvergenceError           | MOORDYN_NAN_ERROR           |
/// | OutputError                | MOORDYN_INVALID_OUTPUT_FILE |
/// | std::bad_alloc             | MOORDYN_MEM_ERROR           |
/// | anything else              | MOORDYN_UNHANDLED_ERROR     |
///
/// ConvergenceError (the statics or a time step that cannot be solved) maps to MOORDYN_NAN_ERROR because
/// that is MoorDyn's code for "the dynamics cannot go on" (its integrators stop on a NaN state), so hosts
/// that handle that case handle this one; the message says what really happened.

#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>

#include "MoorDyn2.h"
#include "tangle/capi/MoorDynSystem.hpp"

namespace tangle::capi {

/// Every open system. A MoorDyn handle is the address of a system held here; closing removes it, so a
/// closed or foreign handle is recognised (MOORDYN_INVALID_VALUE) rather than dereferenced.
class SystemRegistry {
 public:
  static SystemRegistry& instance();
  /// Takes ownership; returns the handle.
  MoorDyn add(std::unique_ptr<MoorDynSystem> system);
  /// The system behind a handle, or null when the handle is null or not open.
  MoorDynSystem* find(MoorDyn handle) const;
  /// Destroys the system; false when the handle is not open.
  bool remove(MoorDyn handle);

 private:
  mutable std::mutex m_mutex;
  std::unordered_map<const void*, std::unique_ptr<MoorDynSystem>> m_systems;
};

inline MoorDynLine toHandle(LineHandle* line) { return reinterpret_cast<MoorDynLine>(line); }
inline MoorDynPoint toHandle(PointHandle* point) { return reinterpret_cast<MoorDynPoint>(point); }

/// Prints "tangle (MoorDyn API): <function>: <message>" through the system's log at MOORDYN_ERR_LEVEL, or
/// on stderr when there is no system.
void reportError(MoorDynSystem* system, const char* function, const std::string& message) noexcept;

/// Maps the exception being handled to its code (table above) and reports it. Call only inside a catch.
int handleCurrentException(MoorDynSystem* system, const char* function) noexcept;

/// The output argument `p`, which must not be null. @throws InvalidValue naming `name`
template <class T>
T& output(T* p, const char* name) {
  if (p == nullptr) throw InvalidValue(std::string(name) + " is NULL");
  return *p;
}

/// Runs body(system) on the open system behind `handle`: MOORDYN_SUCCESS, or the code of what it threw;
/// MOORDYN_INVALID_VALUE for a null or closed handle.
template <class Body>
int withSystem(const char* function, MoorDyn handle, Body&& body) noexcept {
  MoorDynSystem* system = SystemRegistry::instance().find(handle);
  if (system == nullptr) {
    reportError(nullptr, function,
                handle == nullptr ? "the system is NULL"
                                  : "the system is not open (closed, or not from MoorDyn_Create)");
    return MOORDYN_INVALID_VALUE;
  }
  try {
    body(*system);
    return MOORDYN_SUCCESS;
  } catch (...) {
    return handleCurrentException(system, function);
  }
}

/// Runs body(system, index) for an object handle (a line's, point's or rod's: `Object` is LineHandle,
/// PointHandle or RodHandle, `what` its name in the message); MOORDYN_INVALID_VALUE for a null one.
template <class Object, class Handle, class Body>
int withObject(const char* function, Handle handle, const char* what, Body&& body) noexcept {
  if (handle == nullptr) {
    reportError(nullptr, function, std::string("the ") + what + " is NULL");
    return MOORDYN_INVALID_VALUE;
  }
  const Object& object = *reinterpret_cast<const Object*>(handle);
  try {
    body(*object.system, object.index);
    return MOORDYN_SUCCESS;
  } catch (...) {
    return handleCurrentException(object.system, function);
  }
}

/// Runs body(system, line index) for a line handle; MOORDYN_INVALID_VALUE for a null one.
template <class Body>
int withLine(const char* function, MoorDynLine handle, Body&& body) noexcept {
  return withObject<LineHandle>(function, handle, "line", std::forward<Body>(body));
}

/// Runs body(system, point index) for a point handle; MOORDYN_INVALID_VALUE for a null one.
template <class Body>
int withPoint(const char* function, MoorDynPoint handle, Body&& body) noexcept {
  return withObject<PointHandle>(function, handle, "point", std::forward<Body>(body));
}

/// Runs body(system, rod index) for a rod handle; MOORDYN_INVALID_VALUE for a null one.
template <class Body>
int withRod(const char* function, MoorDynRod handle, Body&& body) noexcept {
  return withObject<RodHandle>(function, handle, "rod", std::forward<Body>(body));
}

/// Runs body(system, body index) for a body handle; MOORDYN_INVALID_VALUE for a null one.
template <class Body>
int withBody(const char* function, MoorDynBody handle, Body&& body) noexcept {
  return withObject<BodyHandle>(function, handle, "body", std::forward<Body>(body));
}

/// @throws NotImplemented with the message "not implemented by tangle: <why>" (the guards prefix the
///         function's name)
[[noreturn]] void throwNotImplemented(const std::string& why);

}  // namespace tangle::capi
