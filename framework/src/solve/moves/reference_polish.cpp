// The reference's last word on the fit (polish_with_reference).
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"

namespace hilight {

namespace {

class ReferencePolish final : public Move {
public:
  ReferencePolish(bool keep_count, int rounds) : m_keep_count(keep_count), m_rounds(rounds) {}
  std::string name() const override { return "reference polish"; }
  std::string premise_fails(const SolveContext&, const Fit& fit) const override {
    return fit.lights.empty() ? "no lights" : std::string();
  }
  Fit run(SolveContext& ctx, const Fit& fit) override {
    return polish_with_reference(ctx, ctx.samples, fit.lights, m_keep_count, m_rounds);
  }

private:
  bool m_keep_count;
  int m_rounds;
};

} // namespace

std::shared_ptr<Move> reference_polish_move(bool keep_count, int rounds) {
  return std::make_shared<ReferencePolish>(keep_count, rounds);
}

} // namespace hilight
