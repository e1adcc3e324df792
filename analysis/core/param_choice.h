// granpen analysis: a study's parameter taken from the first source that gives it: an
// option, the push's trace header, else a fallback (the first frame, a measurement, a
// default), the source named for the provenance that flow.json and momentum.json record.
// Used by flow_study_params and momentum_study_params alike.
#ifndef GRANPEN_PARAM_CHOICE_H
#define GRANPEN_PARAM_CHOICE_H

#include <limits>
#include <string>

namespace granpen {

// What an option and the trace header give (NaN: that source does not give it).
struct ParamChoice {
  double option = std::numeric_limits<double>::quiet_NaN();
  double trace = std::numeric_limits<double>::quiet_NaN();
};

// The first of c.option and c.trace that is finite, with origin "option" or "trace"; else
// fallback, with origin fallback_origin.
double resolve(const ParamChoice &c, double fallback, const char *fallback_origin, std::string &origin);

}    // namespace granpen

#endif
