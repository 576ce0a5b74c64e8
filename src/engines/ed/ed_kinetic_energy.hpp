// Kinetic energy of an ED system split by degree of freedom [J] (Luding Fig. 8b uses K_x - K_y).
#pragma once

namespace granrepro {

struct EdKineticEnergy {
    double kx = 0.0;   // sum m vx^2 / 2 [J]
    double ky = 0.0;   // sum m vy^2 / 2 [J]
    double krot = 0.0; // sum I w^2 / 2 [J], I = q m a^2
    double total() const { return kx + ky + krot; }
    double translational() const { return kx + ky; }
};

} // namespace granrepro
