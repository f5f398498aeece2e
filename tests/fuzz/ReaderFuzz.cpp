/// @file ReaderFuzz.cpp
/// libFuzzer harness of the model reader and the MoorDyn deck reader (and its conversion, read back by the
/// model reader): any byte string must either read as a model or be refused with tangle::InputError. Any other exception, a crash, a sanitizer report, a hang (libFuzzer's
/// -timeout) or runaway memory (-rss_limit_mb) is a finding. Built and run by scripts/fuzz-reader.sh.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "tangle/core/Error.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/MoorDynConversion.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)tangle::io::readModelString(text, "fuzz.yaml");
  } catch (const tangle::InputError&) {
    // A refused model is the expected outcome for most inputs.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reader threw something other than InputError: %s\n", e.what());
    std::abort();
  }
  try {
    const tangle::io::MoorDynConversion c =
        tangle::io::convertMoorDynDeck(tangle::io::parseMoorDynDeck(text, "fuzz.txt"));
    (void)tangle::io::readModelString(c.yaml, "fuzz-converted.yaml");
  } catch (const tangle::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "deck reader threw something other than InputError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
