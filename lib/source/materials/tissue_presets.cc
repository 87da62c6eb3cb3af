#include <softgrasp/base/input_error.h>
#include <softgrasp/materials/tissue_presets.h>

namespace softgrasp
{
  // Parameter values and their sources are tabulated in doc/materials.md;
  // keep the two in step. Longer than 80 lines on purpose: one table.
  const std::vector<TissuePresets::Preset> &TissuePresets::all()
  {
    static const std::vector<Preset> presets = {
        {"skin",
         "one-term Ogden fit of pig skin, mu = 0.4 MPa, alpha = 12 (Shergold "
         "et "
         "al. 2006); rho from IT'IS v4.1",
         R"(set Model = Ogden
set Density = 1109
subsection Volumetric
  set Energy = Simo-Taylor
  set Poisson's ratio = 0.48
end
subsection Ogden
  set Moduli = 66666.6667
  set Exponents = 12
end
)"},
        {"subcutaneous fat",
         "neo-Hookean, mu = 0.53 kPa, porcine subdermal fat (Sims et al. "
         "2010); "
         "rho from IT'IS v4.1",
         R"(set Model = neo-Hookean
set Density = 911
subsection Volumetric
  set Energy = Simo-Taylor
  set Poisson's ratio = 0.49
end
subsection neo-Hookean
  set Shear modulus = 530
end
)"},
        {"skeletal muscle",
         "HGO, one fibre family along x; mu and k1 from the cross- and "
         "along-fibre moduli 22.4 and 447 kPa (Morrow et al. 2010); rho from "
         "IT'IS v4.1",
         R"(set Model = Holzapfel-Gasser-Ogden
set Density = 1090
subsection Volumetric
  set Energy = Simo-Taylor
  set Poisson's ratio = 0.49
end
subsection Holzapfel-Gasser-Ogden
  set Shear modulus = 7466.67
  set k1 = 106150
  set k2 = 1
  set Dispersion kappa = 0
  set Number of fibre families = 1
  subsection Fibre direction 1
    set Function expression = 1; 0; 0
  end
end
)"},
        {"fascia",
         "HGO, one fibre family along x; k1 from the longitudinal modulus "
         "397 MPa of fascia lata (Butler et al. 1984), matrix as ligament",
         R"(set Model = Holzapfel-Gasser-Ogden
set Density = 1142
subsection Volumetric
  set Energy = Simo-Taylor
  set Poisson's ratio = 0.49
end
subsection Holzapfel-Gasser-Ogden
  set Shear modulus = 3.6667e6
  set k1 = 96.5e6
  set k2 = 1
  set Dispersion kappa = 0
  set Number of fibre families = 1
  subsection Fibre direction 1
    set Function expression = 1; 0; 0
  end
end
)"},
        {"ligament",
         "HGO, one fibre family along x; mu and k1 from the transverse and "
         "longitudinal moduli 11.0 and 332.2 MPa of human MCL (Quapp and Weiss "
         "1998); rho from IT'IS v4.1",
         R"(set Model = Holzapfel-Gasser-Ogden
set Density = 1142
subsection Volumetric
  set Energy = Simo-Taylor
  set Poisson's ratio = 0.49
end
subsection Holzapfel-Gasser-Ogden
  set Shear modulus = 3.6667e6
  set k1 = 80.3e6
  set k2 = 1
  set Dispersion kappa = 0
  set Number of fibre families = 1
  subsection Fibre direction 1
    set Function expression = 1; 0; 0
  end
end
)"},
        {"natural rubber",
         "three-term Ogden fit of Treloar's data (Ogden 1972), mu_0 = 422.5 "
         "kPa; kappa = 2 GPa and rho = 930 kg/m^3 (Gent 2012)",
         R"(set Model = Ogden
set Density = 930
subsection Volumetric
  set Energy = Simo-Taylor
  set Bulk modulus = 2e9
end
subsection Ogden
  set Moduli = 0.63e6, 0.0012e6, -0.01e6
  set Exponents = 1.3, 5.0, -2.0
end
)"},
        {"cortical bone",
         "stiff neo-Hookean solid, E = 17.9 GPa (Reilly and Burstein 1975), "
         "nu = 0.3; rho from IT'IS v4.1",
         R"(set Model = neo-Hookean
set Density = 1908
subsection Volumetric
  set Energy = Simo-Taylor
  set Poisson's ratio = 0.3
end
subsection neo-Hookean
  set Shear modulus = 6.8846e9
end
)"}};
    return presets;
  }

  const TissuePresets::Preset &TissuePresets::get(const std::string &name)
  {
    for (const Preset &preset : all())
      if (preset.name == name)
        return preset;
    std::string names;
    for (const Preset &preset : all())
      names += (names.empty() ? "" : ", ") + preset.name;
    throw InputError("Unknown tissue preset '" + name +
                     "'. Valid names are: " + names + ".");
  }

  std::string TissuePresets::selection()
  {
    std::string out = "none";
    for (const Preset &preset : all())
      out += "|" + preset.name;
    return out;
  }
} // namespace softgrasp
