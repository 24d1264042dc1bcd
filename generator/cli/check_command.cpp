/** @file check_command.cpp  `eomgen check`: loading the model, the derivation and the map, checking, printing the
 * report. */
#include "cli/check_command.hpp"

#include "checker/checker.hpp"
#include "checker/report.hpp"
#include "checker/symbol_map.hpp"
#include "model/model_file.hpp"
#include "output/atomic_file.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <fstream>
#include <iostream>

namespace eomgen::cli {

using namespace checker;

CheckCommand::CheckCommand(CLI::App& app) {
    command_ = app.add_subcommand(
        "check", "Compare each equation of a derivation (Markdown + LaTeX) with the model's");
    command_->add_option("model", model_, "Model file (.toml)")->required()->check(CLI::ExistingFile);
    command_->add_option("derivation", derivation_, "Derivation text (Markdown with LaTeX math)")
        ->required()
        ->check(CLI::ExistingFile);
    command_->add_option("--section", sections_, "Only sections whose heading contains TEXT (repeatable)")
        ->allow_extra_args(false);
    command_->add_option("--format", format_, "Report format")
        ->check(CLI::IsMember({"text", "markdown", "json"}))
        ->capture_default_str();
    command_->add_option("--map", maps_, "NAME=VALUE: the text's LaTeX name stands for VALUE (repeatable)")
        ->allow_extra_args(false);
    command_
        ->add_option("--map-file", map_files_, "TOML file with a [latex] table of NAME = VALUE (repeatable)")
        ->check(CLI::ExistingFile)
        ->allow_extra_args(false);
    command_->add_option("--set", sets_, "NAME=VALUE: a parameter's value for the numbers the text works out "
                                          "(repeatable)")
        ->allow_extra_args(false);
    command_->add_option("-o,--output", output_, "Write the report to FILE instead of standard output");
}

bool CheckCommand::selected() const {
    return command_ && command_->parsed();
}

int CheckCommand::run() const {
    const Model model = load_model(model_);
    const Equations eq = derive_equations(model);
    CheckOptions options;
    options.sections = sections_;
    try {
        for (const std::string& f : map_files_)
            for (MapEntry& e : load_map_file(f)) options.map.push_back(std::move(e));
        for (const std::string& m : maps_) options.map.push_back(parse_map_option(m));
        for (const std::string& a : sets_) options.set.push_back(parse_set_option(a));
    } catch (const CheckError& e) {
        std::cerr << "eomgen check: " << e.what() << "\n";
        return 2;
    }
    Derivation derivation;
    try {
        derivation = read_derivation(derivation_);
    } catch (const std::runtime_error& e) {
        std::cerr << "eomgen check: " << e.what() << "\n";
        return 3;
    }
    CheckReport report;
    try {
        report = check_derivation(model, eq, derivation, options);
    } catch (const CheckError& e) {
        std::cerr << "eomgen check: " << e.what() << "\n";
        return 2;
    }
    const std::string text = format_ == "json"       ? format_json(report)
                             : format_ == "markdown" ? format_markdown(report)
                                                     : format_text(report);
    if (output_.empty()) {
        std::cout << text;
    } else {
        try {  // a report appears whole or not at all (an interrupted check leaves no half of one)
            output::write_atomically(output_, text);
        } catch (const output::WriteError& e) {
            std::cerr << "eomgen check: " << e.what() << "\n";
            return 3;
        }
    }
    return report.count(Verdict::Disagrees) > 0 ? kExitDisagrees : 0;
}

}  // namespace eomgen::cli
