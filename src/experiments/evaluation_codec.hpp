#pragma once
// An Evaluation as bytes and back, exactly (doubles bit for bit), so that runs made in worker
// processes come back to the parent as if they had run there.

#include <string>
#include <vector>

#include "experiments/evaluation.hpp"

namespace fragsim {

std::string encode_evaluation(const Evaluation& e);
// Throws std::runtime_error on truncated or malformed bytes.
Evaluation decode_evaluation(const std::string& bytes);

// Several evaluations, length-prefixed, as one worker task holds them (a sweep job's strategies, a
// suite run's variants). Throws std::runtime_error like decode_evaluation.
std::string encode_evaluations(const std::vector<Evaluation>& evaluations);
std::vector<Evaluation> decode_evaluations(const std::string& bytes);

}  // namespace fragsim
