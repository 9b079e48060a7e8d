// osgglyphbondbench: the cost of drawing bonds beside their atoms.

#ifndef OSGGLYPHBONDBENCH_BONDRENDERCOST_H
#define OSGGLYPHBONDBENCH_BONDRENDERCOST_H 1

#include <cstddef>

/** Draws random atoms as spheres of 0.4 times their mean spacing, alone and then with their bonds
 * within the cutoff that gives each about bondsPerAtom of them (exact half-bond cylinders of the
 * default bond radius), headless at width x height over frames frames orbiting the box, and prints
 * both median frame times and their ratio. Returns the exit status. */
int measureBondRenderCost(std::size_t atoms, double bondsPerAtom, unsigned int frames, int width, int height);

#endif
