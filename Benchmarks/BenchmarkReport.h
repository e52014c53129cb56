/**
 * @file BenchmarkReport.h
 * @brief PrincipalCurvatureBenchmark's report: the Markdown tables printed
 * on stdout after the measurements (whole filter, scaling, memory, phases,
 * fits alone, peer, targets), and the figures derived for them (scaling
 * exponents, phase times, fits alone, peer) as CSV rows.
 */
#ifndef BenchmarkReport_h
#define BenchmarkReport_h

#include "BenchmarkResults.h"

namespace pcurv
{
namespace benchmark
{

/// Prints every table the results have data for, in the order above.
void PrintSummary(const Options& options, const Results& results, CsvFile& csv);

} // namespace benchmark
} // namespace pcurv

#endif
