/**
 * @file TestChecks.h
 * @brief A few named checks that count failures and print what failed, for
 * the plain C++ tests (VTK style: main returns EXIT_SUCCESS/EXIT_FAILURE).
 */
#ifndef TestChecks_h
#define TestChecks_h

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

/// Whether the tests run under AddressSanitizer (Scripts/sanitize.sh). There
/// the tests that are studies as well (sweeps of settings to compare with)
/// leave the sweeps out: they exercise no code the single runs do not, and
/// the sanitizers make them several times slower. The unsanitized run
/// checks them.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) // clang's way of saying it
#define PCURV_ADDRESS_SANITIZER
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(PCURV_ADDRESS_SANITIZER) // GCC's, clang's
constexpr bool UnderSanitizers = true;
#else
constexpr bool UnderSanitizers = false;
#endif

/// The whole file as text ("" when it cannot be read).
inline std::string ReadTextFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

class Checks
{
public:
  void True(const char* what, bool ok)
  {
    ++this->Count;
    if (!ok)
    {
      this->Fail(what, "is false");
    }
  }

  void Near(const char* what, double value, double expected, double tolerance)
  {
    ++this->Count;
    if (!(std::fabs(value - expected) <= tolerance))
    {
      char detail[160];
      std::snprintf(
        detail, sizeof(detail), "= %.10g, expected %.10g +- %.3g", value, expected, tolerance);
      this->Fail(what, detail);
    }
  }

  void Below(const char* what, double value, double limit)
  {
    ++this->Count;
    if (!(value < limit))
    {
      char detail[160];
      std::snprintf(detail, sizeof(detail), "= %.6g, must be below %.6g", value, limit);
      this->Fail(what, detail);
    }
  }

  void AtLeast(const char* what, double value, double limit)
  {
    ++this->Count;
    if (!(value >= limit))
    {
      char detail[160];
      std::snprintf(detail, sizeof(detail), "= %.6g, must be at least %.6g", value, limit);
      this->Fail(what, detail);
    }
  }

  void Equal(const char* what, long long value, long long expected)
  {
    ++this->Count;
    if (value != expected)
    {
      char detail[160];
      std::snprintf(detail, sizeof(detail), "= %lld, expected %lld", value, expected);
      this->Fail(what, detail);
    }
  }

  int Summary() const
  {
    std::printf("%d checks, %d failed\n", this->Count, this->Failures);
    // A test that checked nothing has not passed.
    return this->Failures == 0 && this->Count > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
  }

private:
  void Fail(const char* what, const char* detail)
  {
    ++this->Failures;
    if (this->Failures <= 50)
    {
      std::printf("FAILED: %s %s\n", what, detail);
    }
  }

  int Count = 0;
  int Failures = 0;
};

/// A test of a group, by the name CTest knows it by.
struct NamedTest
{
  const char* Name;
  void (*Run)(Checks&);
};

/// Runs the test named by the first argument (the CTest of that name), or
/// every test without one; an unknown name fails, so that a test renamed in
/// one place and not the other cannot pass by running nothing.
inline int RunNamedTests(int argc, char* argv[], std::initializer_list<NamedTest> tests)
{
  Checks checks;
  bool found = argc < 2;
  for (const NamedTest& test : tests)
  {
    if (argc < 2 || std::strcmp(test.Name, argv[1]) == 0)
    {
      std::printf("%s\n", test.Name);
      test.Run(checks);
      found = true;
    }
  }
  if (!found)
  {
    std::printf("FAILED: no test named %s\n", argv[1]);
    return EXIT_FAILURE;
  }
  return checks.Summary();
}

#endif
