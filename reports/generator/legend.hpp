#pragma once
// The legends of the summary page: what each verdict means, and how strong each kind of evidence is.
#include <sstream>

namespace affinterp::report {

void write_verdict_legend(std::ostringstream& md);
void write_strength_legend(std::ostringstream& md);

}  // namespace affinterp::report
