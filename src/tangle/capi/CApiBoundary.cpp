#include "tangle/capi/CApiBoundary.hpp"

#include <exception>
#include <iostream>
#include <new>

namespace tangle::capi {

SystemRegistry& SystemRegistry::instance() {
  static SystemRegistry registry;
  return registry;
}

MoorDyn SystemRegistry::add(std::unique_ptr<MoorDynSystem> system) {
  const std::lock_guard<std::mutex> lock(m_mutex);
  MoorDynSystem* raw = system.get();
  m_systems.emplace(raw, std::move(system));
  return reinterpret_cast<MoorDyn>(raw);
}

MoorDynSystem* SystemRegistry::find(MoorDyn handle) const {
  if (handle == nullptr) return nullptr;
  const std::lock_guard<std::mutex> lock(m_mutex);
  const auto it = m_systems.find(reinterpret_cast<const void*>(handle));
  return it == m_systems.end() ? nullptr : it->second.get();
}

bool SystemRegistry::remove(MoorDyn handle) {
  std::unique_ptr<MoorDynSystem> closing;  // destroyed after the lock is released
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_systems.find(reinterpret_cast<const void*>(handle));
    if (it == m_systems.end()) return false;
    closing = std::move(it->second);
    m_systems.erase(it);
  }
  return true;
}

void reportError(MoorDynSystem* system, const char* function, const std::string& message) noexcept {
  try {
    std::string text = "tangle (MoorDyn API): ";
    text += function;
    text += ": ";
    text += message;
    if (text.empty() || text.back() != '\n') text += '\n';
    if (system != nullptr) {
      system->log(MOORDYN_ERR_LEVEL, text);
    } else {
      std::cerr << text << std::flush;
    }
  } catch (...) {
    // Nothing more can be done for a message that cannot be printed (out of memory).
  }
}

int handleCurrentException(MoorDynSystem* system, const char* function) noexcept {
  try {
    throw;
  } catch (const InvalidValue& e) {
    reportError(system, function, e.what());
    return MOORDYN_INVALID_VALUE;
  } catch (const NotImplemented& e) {
    reportError(system, function, e.what());
    return MOORDYN_NON_IMPLEMENTED;
  } catch (const InputError& e) {
    reportError(system, function, e.what());
    return MOORDYN_INVALID_INPUT;
  } catch (const ConvergenceError& e) {
    reportError(system, function, e.what());
    return MOORDYN_NAN_ERROR;
  } catch (const OutputError& e) {
    reportError(system, function, e.what());
    return MOORDYN_INVALID_OUTPUT_FILE;
  } catch (const std::bad_alloc&) {
    reportError(system, function, "out of memory");
    return MOORDYN_MEM_ERROR;
  } catch (const std::exception& e) {
    reportError(system, function, e.what());
    return MOORDYN_UNHANDLED_ERROR;
  } catch (...) {
    reportError(system, function, "unknown error");
    return MOORDYN_UNHANDLED_ERROR;
  }
}

void throwNotImplemented(const std::string& why) {
  throw NotImplemented("not implemented by tangle: " + why);
}

}  // namespace tangle::capi
