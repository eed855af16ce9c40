// cellgen tissue: a packed tissue of polyhedral cells from a Voronoi tessellation (README.md,
// "Tissue mode"; doc/model.md §10.6).
#pragma once

namespace cellgen {

// Runs `cellgen tissue ...`; argv[0] is "tissue". Returns the exit status (0, 1 geometry, 2 usage).
int tissueMain(int argc, char **argv);

}    // namespace cellgen
