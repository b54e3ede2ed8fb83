// Prints the host's SGP4 states for the test vectors of a TLE file in the
// layout of Vallado's SGP4-VER.TLE (line 2 carries start, stop and step in
// minutes after column 69), for check_sgp4.py to compare with python3-sgp4.
//
//   sgp4_vectors teme FILE        per satellite "sat N", then per time
//                                 "t MIN X Y Z VX VY VZ" (TEME, km, km/s) or
//                                 "err MIN CODE" (the run of that satellite stops)
//   sgp4_vectors j2000 FILE MIN   per satellite at epoch + MIN minutes:
//                                 "sat N JD_UTC X Y Z VX VY VZ" in J2000 (m, m/s)
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "scenario.hpp"
#include "sgp4.hpp"

using eoir::cli::Sgp4;
using eoir::cli::Sgp4Error;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: sgp4_vectors teme|j2000 FILE [MINUTES]\n";
    return 1;
  }
  const std::string mode = argv[1];
  std::ifstream in(argv[2]);
  if (!in) {
    std::cerr << "cannot open " << argv[2] << "\n";
    return 1;
  }
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    if (lines[i].rfind("1 ", 0) != 0 || lines[i + 1].rfind("2 ", 0) != 0) continue;
    const std::string l1 = lines[i], l2 = lines[i + 1];
    const Sgp4 sat = Sgp4::from_tle(l1, l2.substr(0, 69), false);
    if (mode == "j2000") {
      const double minutes = std::stod(argv[3]);
      const double t_s = ((sat.epoch_jd() - 2451545.0) + sat.epoch_jd_fraction()) * 86400.0 + minutes * 60.0;
      try {
        const eoir::cli::PosVel s = eoir::cli::tle_state_j2000(sat, t_s);
        std::printf("sat %ld %.12f %.6f %.6f %.6f %.9f %.9f %.9f\n", sat.satellite_number(),
                    2451545.0 + t_s / 86400.0, s.position[0], s.position[1], s.position[2], s.velocity[0],
                    s.velocity[1], s.velocity[2]);
      } catch (const Sgp4Error& e) {
        std::printf("err %ld %d\n", sat.satellite_number(), e.code());
      }
      continue;
    }
    std::printf("sat %ld\n", sat.satellite_number());
    double start = 0, stop = 0, step = 0;
    std::istringstream(l2.substr(69)) >> start >> stop >> step;
    // The times of python-sgp4's generate_satellite_output.
    std::vector<double> times{0.0};
    double t = start;
    for (; t <= stop; t += step) {
      if (t == start && start == 0.0) continue;
      times.push_back(t);
    }
    if (t - stop < step - 1e-6) times.push_back(stop);
    for (double m : times) {
      try {
        const eoir::cli::TemeState s = sat.at_minutes(m);
        std::printf("t %.8f %.8f %.8f %.8f %.9f %.9f %.9f\n", m, s.r_km[0], s.r_km[1], s.r_km[2], s.v_km_s[0],
                    s.v_km_s[1], s.v_km_s[2]);
      } catch (const Sgp4Error& e) {
        std::printf("err %.8f %d\n", m, e.code());
        break;
      }
    }
  }
  return 0;
}
