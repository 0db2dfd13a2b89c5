"""The answers of the 3D chapter: transformations in homogeneous coordinates (`transform`) and
projections (`project`), and their shared text of points and matrices in 4 x 4."""
