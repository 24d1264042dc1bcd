/** @file prose.hpp  The prose around a derivation's math, as the readings of its roles need it (conditions.hpp,
 * meanings.hpp, equivalent_lagrangian.hpp, the labels): the sentences that lead into a display, the sentence
 * that holds an inline formula. Lower case, for cue words. */
#pragma once

#include "checker/derivation.hpp"

#include <cstddef>
#include <initializer_list>
#include <string>

namespace eomgen::checker {

/**
 * The prose that leads into the math at `offset`, lower case: the paragraph's text before that math (its inline
 * math left out), from the start of its last `sentences` sentences; a display set off by a blank line takes the
 * paragraph before it (up to two back).
 */
std::string lead_in(const Derivation& d, std::size_t offset, int sentences);

/// The sentence that holds text[begin, end): from the sentence end (or blank line) before it to the one after it,
/// prose and math alike, lower case.
std::string sentence_around(const std::string& text, std::size_t begin, std::size_t end);

/// The last word of the prose leading into the math at `offset` (lead_in's, one sentence) when it is one of
/// `words` ("linearizing about", "Setting"), else "": what the math right after it is.
std::string lead_in_ends_with(const Derivation& d, std::size_t offset, std::initializer_list<const char*> words);

/// True when the math at `offset` is said to explain a formula before it: the word right before it is "where",
/// "with", "donde" (`… - \omega^2 r \quad \text{where $\omega^2 = k/m$}`), or the sentence leading into it starts
/// with "where" ("where $Q$ is the force of the damper: $$Q = -c\dot y$$").
bool explains_formula_before(const Derivation& d, std::size_t offset);

/// True when the sentence leading into the math at `offset` introduces a name: "let", "define", "introduce",
/// "denote", "call", "write" as words ("Let $\omega_c^2 = g/R$", "introduce the critical rate through $…$").
bool introduces_name(const Derivation& d, std::size_t offset);

/**
 * The end of the paragraph that holds `at`, as a reader takes it: the next blank line, or past it when the prose
 * before the blank line runs on into a display set off by blank lines (it ends without a full stop: "and dividing
 * by $\sin\theta$," then `$$…$$` alone in its paragraph), and so on while each display runs on into the next.
 * The conditions of a steady motion stated in a paragraph hold for the displays it runs on into (discourse.cpp).
 */
std::size_t paragraph_end(const Derivation& d, std::size_t at);

}  // namespace eomgen::checker
