// The runner of the whole-answer alternatives: the one place that decides
// which answer is kept and carries what a losing solve logged.
#include "hilight/solve/alternative.hpp"

#include "solver_internal.hpp"

namespace hilight {

using solver_detail::Stopwatch;

namespace {

/// A candidate's report starts with the answer's log and timings (what was
/// tried stays logged whichever answer is kept) and where it was sought.
SolveReport candidate_report(const SolveReport& answer) {
  SolveReport report;
  report.seconds = answer.seconds;
  report.stages = answer.stages;
  report.open_space = answer.open_space;
  report.dbar_closed = answer.dbar_closed;
  return report;
}

} // namespace

Answer run_alternatives(const Alternatives& alternatives, AlternativeContext& ctx, Answer answer) {
  for (const auto& alternative : alternatives) {
    if (std::string why = alternative->premise_fails(ctx, answer); !why.empty()) {
      answer.report.stages.push_back({alternative->name(), 0, answer.report.dbar, answer.report.dbar, true, false, std::move(why)});
      continue;
    }
    const std::vector<std::string> names = alternative->candidates();
    for (size_t i = 0; i < names.size(); ++i) {
      Stopwatch watch;
      Answer candidate;
      candidate.report = candidate_report(answer.report);
      candidate.lights = alternative->propose(ctx, answer, i, candidate.report);
      const bool wins = alternative->wins(ctx.judge(), candidate, answer);
      StageRecord record{names[i], watch.seconds(), answer.report.dbar, candidate.report.dbar, true, wins, {}};
      if (wins) {
        alternative->kept(ctx, candidate, answer);
        answer = std::move(candidate);
      } else {
        answer.report.seconds = std::move(candidate.report.seconds);
        answer.report.stages = std::move(candidate.report.stages);
        alternative->rejected(ctx, answer);
      }
      answer.report.stages.push_back(std::move(record));
    }
  }
  return answer;
}

} // namespace hilight
