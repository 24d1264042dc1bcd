/** @file verdict.cpp  The names the reports give verdicts and roles. */
#include "checker/verdict.hpp"

namespace eomgen::checker {

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::Agrees:
            return "agrees";
        case Verdict::Disagrees:
            return "disagrees";
        case Verdict::NotComparable:
            return "not comparable";
        case Verdict::NotRead:
            return "not read";
        case Verdict::NotJudged:
            return "not judged";
    }
    return "";
}

const char* role_name(Role r) {
    switch (r) {
        case Role::Claim:
            return "claim";
        case Role::Definition:
            return "definition";
        case Role::Assumption:
            return "assumption";
        case Role::Condition:
            return "condition";
        case Role::Trial:
            return "trial solution";
        case Role::ChosenValue:
            return "chosen value";
    }
    return "";
}

}  // namespace eomgen::checker
