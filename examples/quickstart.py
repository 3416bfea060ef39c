"""Quick start: solve the seed A bearing at speed and print its stiffness.

python3 examples/quickstart.py
"""

import numpy as np

import thermobear as tb

b = tb.Bearing.preset("6208")
s = b.solve(axial_n=2680.9, radial_n=1189.9, speed_rpm=16000)
print(f"axial displacement  {s.axial_displacement_um:8.2f} um")
print(f"radial displacement {s.radial_displacement_um:8.2f} um")
print(f"radial stiffness    {s.k_xx_n_per_m / 1e6:8.1f} N/um (k_xx, full 5x5)")
print(f"  seed formula      {s.radial_stiffness_seed_n_per_m / 1e6:8.1f} N/um (seed A eq. 41)")
print(f"axial stiffness     {s.k_zz_n_per_m / 1e6:8.1f} N/um (k_zz, full 5x5)")
print(f"  seed formula      {s.axial_stiffness_seed_n_per_m / 1e6:8.1f} N/um (seed A eq. 39)")
print(s.balls.select("azimuth_deg", "inner_load_n", "outer_load_n", "inner_contact_angle_deg"))
df = tb.stiffness_curve(b, np.linspace(6500, 16500, 11), 2680.9, 1189.9)
print(df.select("speed_rpm", "k_xx_n_per_m", "radial_stiffness_seed_n_per_m", "k_zz_n_per_m"))
