// Catch2's main for every tutorial check, compiled once (it takes a while). After the
// checks it says in one line whether the exercise is solved, and where to look if not.
#define CATCH_CONFIG_RUNNER
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <filesystem>

#include <catch2/catch.hpp>

#include "geometry/student_code.h"
#include "tutorial_picture.h"

int main(int argc, char* argv[]) {
    // Pictures are named after the program: tutorial_03_exercise-hull.png, ...
    if (argc > 0) tutorial::programName = std::filesystem::path(argv[0]).filename().string();
    // Every value a failed check prints, at full precision: two doubles that differ in the
    // last place must not look alike
    Catch::StringMaker<double>::precision = 17;
    Catch::StringMaker<float>::precision = 9;
    int failed = Catch::Session().run(argc, argv);
    // A hole's stub as shipped says so when it runs (rc::notYet): whatever it passes by
    // chance, the exercise is not done (tutorial_NN_...: NN from the program's name)
    const std::string& name = tutorial::programName;
    const int nn = name.size() > 11 && name.compare(0, 9, "tutorial_") == 0 ? std::atoi(name.substr(9, 2).c_str()) : 0;
    if (nn > 0 && rc::stubRan(nn)) {
        std::printf("\nNOT YET: tutorial %02d's function is still the stub as shipped.\n", nn);
        failed = std::max(failed, 1);
    }
    // A check that runs the renderer runs the earlier tutorials' holes too: when one of them
    // is still its stub, a correct answer here can fail for that alone, so the verdict names
    // the earliest such tutorial to do first (one sentence, the renderer's own for tutorial 01).
    // Only earlier ones: a later tutorial's stub (06's textbook roots in every render) is what
    // a student working in order still has, and is never a reason to skip ahead. Nothing is
    // named when this tutorial's own stub ran: that is the first thing to do.
    std::string first;
    for (int k = 1; k < nn && first.empty() && !rc::stubRan(nn); ++k)
        if (rc::stubRan(k))
            first = k == 1 ? rc::cannotDrawYet()
                           : "This check ran tutorial " + rc::tutorialNumber(k) +
                                 "'s stub as shipped, so do tutorial " + rc::tutorialNumber(k) + " first.";
    if (failed == 0) {
        std::printf("\nSOLVED: every check passes.\n");
    } else {
        std::printf(
            "\nNOT YET: %d assertion(s) failed. Read the first failure above: its test case says what\n"
            "is checked, and the lines after \"with message(s):\" give the case, the\n"
            "expected value and yours. The tutorial's page has hints, from a nudge to a\n"
            "near-solution.\n",
            failed);
        if (!first.empty()) std::printf("%s\n", first.c_str());
    }
    return failed;
}
