# Writes the data of the osgglyphviewer tests into DIR (cmake -DDIR=... -P WriteViewerTestData.cmake):
#   spheres.lammpstrj    LAMMPS dump custom, 2 frames of 5 atoms (id type x y z vx vy vz) in a box of
#                        -2..2; frame 0 has an atom at the origin and four at distinct depths around
#                        it (the positions tests/viewer/ViewerTest.cmake checks depth at)
#   malformed.lammpstrj  the same with 'zero' for a coordinate on line 12
#   still.csv            three points whose velocities are all zero
#   huge.csv             two points 3e38 from the origin, as far as float goes
#   near.csv, far.csv    frame 0 of spheres.lammpstrj, and the same moved by 1e7 on each axis
#   vast.csv             points 1e17 apart
cmake_minimum_required(VERSION 3.25)

# viewer_frame(<out> <timestep> <atom lines...>): one frame of a dump.
function(viewer_frame out timestep)
    set(text "ITEM: TIMESTEP\n${timestep}\nITEM: NUMBER OF ATOMS\n5\nITEM: BOX BOUNDS pp pp pp\n")
    string(APPEND text "-2 2\n-2 2\n-2 2\nITEM: ATOMS id type x y z vx vy vz\n")
    foreach(atom IN LISTS ARGN)
        string(APPEND text "${atom}\n")
    endforeach()
    set(${out} "${text}" PARENT_SCOPE)
endfunction()

viewer_frame(frame0 0
    "1 1 0 0 0 1 0 0"
    "2 2 1 0.7 0.5 0 1 0"
    "3 1 -1 0.7 -0.5 0 0 1"
    "4 2 1 -0.7 -0.5 -1 1 0"
    "5 1 -1 -0.7 0.3 0.5 0.5 0.5")
viewer_frame(frame1 100
    "1 1 0.3 0.1 0 1 0 0"
    "2 2 1.1 0.8 0.4 0 1 0"
    "3 1 -0.9 0.6 -0.5 0 0 1"
    "4 2 1.2 -0.8 -0.4 -1 1 0"
    "5 1 -1.1 -0.6 0.2 0.5 0.5 0.5")
file(WRITE "${DIR}/spheres.lammpstrj" "${frame0}${frame1}")
string(REPLACE "3 1 -1 0.7 -0.5" "3 1 -1 zero -0.5" malformed "${frame0}")
file(WRITE "${DIR}/malformed.lammpstrj" "${malformed}")
file(WRITE "${DIR}/still.csv" "x,y,z,vx,vy,vz\n-1,0,0,0,0,0\n1,0,0,0,0,0\n0,0,1,0,0,0\n")
file(WRITE "${DIR}/huge.csv" "x,y,z\n3e38,0,0\n-3e38,0,0\n")
file(WRITE "${DIR}/near.csv" "x,y,z\n0,0,0\n1,0.7,0.5\n-1,0.7,-0.5\n1,-0.7,-0.5\n-1,-0.7,0.3\n")
file(WRITE "${DIR}/far.csv" "x,y,z\n10000000,10000000,10000000\n10000001,10000000.7,10000000.5\n"
    "9999999,10000000.7,9999999.5\n10000001,9999999.3,9999999.5\n9999999,9999999.3,10000000.3\n")
file(WRITE "${DIR}/vast.csv" "x,y,z\n0,0,0\n1e17,0,0\n0,1e17,0\n0,0,1e17\n")
