#pragma once
/// \file
/// \brief Which functions of this build are a student's: the tutorials' exercises are holes
/// in RayCache itself (docs/pages/tutorials.md). A student build (`cmake --preset student`)
/// compiles each open tutorial's `tutorials/NN-name/exercise.cpp` in place of the file that
/// holds the function, so the CLI, the GUI and the tutorials' pictures run the student's
/// code. A stub, as shipped, says so by calling notYet().
#include <string>
#include <vector>

namespace rc {

/// One function of the renderer that a tutorial's exercise provides.
struct StudentFunction {
    int tutorial;          ///< 1..7
    std::string function;  ///< e.g. "rc::Hull"
};

/// The functions of this build that come from tutorials/NN-name/exercise.cpp (empty in the
/// instructor's build, `RAYCACHE_STUDENT=OFF`).
const std::vector<StudentFunction>& studentFunctions();

/// Is tutorial `tutorial`'s function the student's in this build?
bool isStudents(int tutorial);

/// "student build: rc::Hull (tutorial 03), ..." or "" in the instructor's build; for
/// window titles and reports.
std::string studentSummary();

/// A tutorial's number as the tutorials name it: "03".
std::string tutorialNumber(int tutorial);

/// Called by a tutorial's stub as shipped: records that tutorial `tutorial`'s stub ran.
void notYet(int tutorial);

/// Has tutorial `tutorial`'s stub run in this process?
bool stubRan(int tutorial);

/// When tutorial 01's stub (the complete search) ran, the renderer cannot draw: the one
/// sentence that says so and which tutorial to do first; "" otherwise.
std::string cannotDrawYet();

/// When the stubs of tutorials other than 01 ran (each as shipped), the one sentence that
/// names them: what was drawn may not be the reference's answers and counts until they are
/// done; "" otherwise.
std::string stubsRanNote();

}  // namespace rc
