// granpen convert FILE --from ave/time ...: a force trace in another format written as a
// granpen-trace v1 file, so that every other subcommand reads it.
#include "convert_options.h"
#include "atomic_file.h"
#include "subcommand.h"
#include "subcommands.h"
#include "trace_reader.h"
#include "text_util.h"
#include "trace_writer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int granpen::cli::run_convert(const ConvertOptions &o)
{
  const std::string &in = o.in, &out = o.out;
  const AveTimeSpec &spec = o.spec;
  refuse_overwriting_inputs(out, "--out", {in});
  try {
    const Trace t = read_ave_time(in, spec);
    TraceHeader h;
    h.units = t.units;
    h.v0 = t.v0;
    h.D = t.D;
    h.g = t.g;
    h.extra = o.extra;
    h.extra.emplace_back("source", t.keys.at("source"));
    std::string text = format_trace_header(h);
    for (std::size_t i = 0; i < t.t.size(); ++i) text += format_trace_row({t.t[i], t.z[i], t.F[i]});
    if (!std::isnan(spec.step0) && t.t.front() < 0.0)
      throw InputError(in + ": --step0 " + std::to_string((long long) spec.step0) +
                       " is after the file's first timestep (t would start at " + printf_number("%g", t.t.front()) + " s)");
    parse_trace(text, out);    // what every other subcommand will read back
    write_file_atomic(out, text);
    std::printf("granpen convert: %s -> %s: %zu rows, t = %.6g to %.6g s, z = %.4g to %.4g\n", in.c_str(), out.c_str(),
                t.t.size(), t.t.front(), t.t.back(), t.z.front(), t.z.back());
    return 0;
  } catch (InputError &e) {
    std::fprintf(stderr, "granpen convert: %s\n", e.what());
    return EXIT_FAILED;
  }
}

int granpen::cli::convert(int argc, char **argv) { return run_parsed(parse_convert, run_convert, argc, argv); }
