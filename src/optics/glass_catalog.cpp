#include "optics/glass_catalog.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace lensrt {
namespace {

// Sellmeier coefficients B1, B2, B3, C1, C2, C3 (C in um^2) from Schott's
// catalogue.
constexpr Sellmeier S(double b1, double b2, double b3, double c1, double c2, double c3) {
  return Sellmeier{{b1, b2, b3}, {c1, c2, c3}};
}

// Current glasses.
constexpr Sellmeier kNBK7 = S(1.03961212, 0.231792344, 1.01046945, 0.00600069867, 0.0200179144, 103.560653);
constexpr Sellmeier kNBK10 = S(0.888308131, 0.328964475, 0.984610769, 0.00516900822, 0.0161190045, 99.7575331);
constexpr Sellmeier kNK5 = S(1.08511833, 0.199562005, 0.930511663, 0.00661099503, 0.024110866, 111.982777);
constexpr Sellmeier kK7 = S(1.1273555, 0.124412303, 0.827100531, 0.00720341707, 0.0269835916, 100.384588);
constexpr Sellmeier kK10 = S(1.15687082, 0.0642625444, 0.872376139, 0.00809424251, 0.0386051284, 104.74773);
constexpr Sellmeier kNKF9 = S(1.19286778, 0.0893346571, 0.920819805, 0.00839154696, 0.0404010786, 112.572446);
constexpr Sellmeier kNFK5 = S(0.844309338, 0.344147824, 0.910790213, 0.00475111955, 0.0149814849, 97.8600293);
constexpr Sellmeier kNFK51A = S(0.971247817, 0.216901417, 0.904651666, 0.00472301995, 0.0153575612, 168.68133);
constexpr Sellmeier kNPK52A = S(1.029607, 0.1880506, 0.736488165, 0.00516800155, 0.0166658798, 138.964129);
constexpr Sellmeier kNPSK3 = S(0.88727211, 0.489592425, 1.04865296, 0.00469824067, 0.0161818463, 104.374975);
constexpr Sellmeier kNPSK53A = S(1.38121836, 0.196745645, 0.886089205, 0.00706416337, 0.0233251345, 97.4847345);
constexpr Sellmeier kNBAK1 = S(1.12365662, 0.309276848, 0.881511957, 0.00644742752, 0.0222284402, 107.297751);
constexpr Sellmeier kNBAK2 = S(1.01662154, 0.319903051, 0.937232995, 0.00592383763, 0.0203828415, 113.118417);
constexpr Sellmeier kNBAK4 = S(1.28834642, 0.132817724, 0.945395373, 0.00779980626, 0.0315631177, 105.965875);
constexpr Sellmeier kNBALF4 = S(1.31004128, 0.142038259, 0.964929351, 0.0079659645, 0.0330672072, 109.19732);
constexpr Sellmeier kNSK2 = S(1.28189012, 0.257738258, 0.96818604, 0.0072719164, 0.0242823527, 110.377773);
constexpr Sellmeier kNSK4 = S(1.32993741, 0.228542996, 0.988465211, 0.00716874107, 0.0246455892, 100.886364);
constexpr Sellmeier kNSK5 = S(0.991463823, 0.495982121, 0.987393925, 0.00522730467, 0.0172733646, 98.3594579);
constexpr Sellmeier kNSK11 = S(1.17963631, 0.229817295, 0.935789652, 0.00680282081, 0.0219737205, 101.513232);
constexpr Sellmeier kNSK14 = S(0.936155374, 0.594052018, 1.04374583, 0.00461716525, 0.016885927, 103.736265);
constexpr Sellmeier kNSK16 = S(1.34317774, 0.241144399, 0.994317969, 0.00704687339, 0.0229005, 92.7508526);
constexpr Sellmeier kNSSK2 = S(1.4306027, 0.153150554, 1.01390904, 0.00823982975, 0.0333736841, 106.870822);
constexpr Sellmeier kNSSK5 = S(1.59222659, 0.103520774, 1.05174016, 0.00920284626, 0.0423530072, 106.927374);
constexpr Sellmeier kNSSK8 = S(1.44857867, 0.117965926, 1.06937528, 0.00869310149, 0.0421566593, 111.300666);
constexpr Sellmeier kNBAF4 = S(1.42056328, 0.102721269, 1.14380976, 0.00942015382, 0.0531087291, 110.278856);
constexpr Sellmeier kNBAF10 = S(1.5851495, 0.143559385, 1.08521269, 0.00926681282, 0.0424489805, 105.613573);
constexpr Sellmeier kNBAF52 = S(1.43903433, 0.0967046052, 1.09875818, 0.00907800128, 0.050821208, 105.691856);
constexpr Sellmeier kNBASF2 = S(1.53652081, 0.156971102, 1.30196815, 0.0108435729, 0.0562278762, 131.3397);
constexpr Sellmeier kNBASF64 = S(1.65554268, 0.17131977, 1.33664448, 0.0104485644, 0.0499394756, 118.961472);
constexpr Sellmeier kNKZFS4 = S(1.35055424, 0.197575506, 1.09962992, 0.0087628207, 0.0371767201, 90.3866994);
constexpr Sellmeier kNKZFS11 = S(1.3322245, 0.28924161, 1.15161734, 0.0084029848, 0.034423972, 88.4310532);
constexpr Sellmeier kNLAK8 = S(1.33183167, 0.546623206, 1.19084015, 0.00620023871, 0.0216465439, 82.5827736);
constexpr Sellmeier kNLAK9 = S(1.46231905, 0.344399589, 1.15508372, 0.00724270156, 0.0243353131, 85.4686868);
constexpr Sellmeier kNLAK10 = S(1.72878017, 0.169257825, 1.19386956, 0.00886014635, 0.0363416509, 82.9009069);
constexpr Sellmeier kNLAK12 = S(1.17365704, 0.588992398, 0.978014394, 0.00577031797, 0.0200401678, 95.4873482);
constexpr Sellmeier kNLAK14 = S(1.50781212, 0.318866829, 1.14287213, 0.00746098727, 0.0242024834, 80.9565165);
constexpr Sellmeier kNLAK22 = S(1.14229781, 0.535138441, 1.04088385, 0.00585778594, 0.0198546147, 100.834017);
constexpr Sellmeier kNLAK33B = S(1.42288601, 0.593661336, 1.1613526, 0.00670283452, 0.021941621, 80.7407701);
constexpr Sellmeier kNLAF2 = S(1.80984227, 0.15729555, 1.0930037, 0.0101711622, 0.0442431765, 100.687748);
constexpr Sellmeier kNLAF21 = S(1.87134529, 0.25078301, 1.22048639, 0.0093332228, 0.0345637762, 83.2404866);
constexpr Sellmeier kNLAF34 = S(1.75836958, 0.313537785, 1.18925231, 0.00872810026, 0.0293020832, 85.1780644);
constexpr Sellmeier kNLASF9 = S(2.00029547, 0.298926886, 1.80691843, 0.0121426017, 0.0538736236, 156.530829);
constexpr Sellmeier kNLASF44 = S(1.78897105, 0.38675867, 1.30506243, 0.00872506277, 0.0308085023, 92.7743824);
constexpr Sellmeier kF2 = S(1.34533359, 0.209073176, 0.937357162, 0.00997743871, 0.0470450767, 111.886764);
constexpr Sellmeier kNF2 = S(1.39757037, 0.159201403, 1.2686543, 0.00995906143, 0.0546931752, 119.248346);
constexpr Sellmeier kF5 = S(1.3104463, 0.19603426, 0.96612977, 0.00958633048, 0.0457627627, 115.011883);
constexpr Sellmeier kLF5 = S(1.28035628, 0.163505973, 0.893930112, 0.00929854416, 0.0449135769, 110.493685);
constexpr Sellmeier kLLF1 = S(1.21640125, 0.13366454, 0.883399468, 0.00857807248, 0.0420143003, 107.59306);
constexpr Sellmeier kSF1 = S(1.55912923, 0.284246288, 0.968842926, 0.0121481001, 0.0534549042, 112.174809);
constexpr Sellmeier kNSF1 = S(1.60865158, 0.237725916, 1.51530653, 0.0119654879, 0.0590589722, 135.521676);
constexpr Sellmeier kSF2 = S(1.40301821, 0.231767504, 0.939056586, 0.0105795466, 0.0493226978, 112.405955);
constexpr Sellmeier kNSF2 = S(1.47343127, 0.163681849, 1.36920899, 0.0109019098, 0.0585683687, 127.404933);
constexpr Sellmeier kSF4 = S(1.61957826, 0.339493189, 1.02566931, 0.0125502104, 0.0544559822, 117.652222);
constexpr Sellmeier kNSF4 = S(1.67780282, 0.282849893, 1.63539276, 0.012679345, 0.0602038419, 145.760496);
constexpr Sellmeier kSF5 = S(1.46141885, 0.247713019, 0.949995832, 0.0111826126, 0.0508594669, 112.041888);
constexpr Sellmeier kNSF5 = S(1.52481889, 0.187085527, 1.42729015, 0.011254756, 0.0588995392, 129.141675);
constexpr Sellmeier kSF6 = S(1.72448482, 0.390104889, 1.04572858, 0.0134871947, 0.0569318095, 118.557185);
constexpr Sellmeier kNSF6 = S(1.77931763, 0.338149866, 2.08734474, 0.0133714182, 0.0617533621, 174.01759);
constexpr Sellmeier kNSF8 = S(1.55075812, 0.209816918, 1.46205491, 0.0114338344, 0.0582725652, 133.24165);
constexpr Sellmeier kSF10 = S(1.61625977, 0.259229334, 1.07762317, 0.0127534559, 0.0581983954, 116.60768);
constexpr Sellmeier kNSF10 = S(1.62153902, 0.256287842, 1.64447552, 0.0122241457, 0.0595736775, 147.468793);
constexpr Sellmeier kSF11 = S(1.73848403, 0.311168974, 1.17490871, 0.0136068604, 0.0615960463, 121.922711);
constexpr Sellmeier kNSF11 = S(1.73759695, 0.313747346, 1.89878101, 0.013188707, 0.0623068142, 155.23629);
constexpr Sellmeier kNSF14 = S(1.69022361, 0.288870052, 1.7045187, 0.0130512113, 0.061369188, 149.517689);
constexpr Sellmeier kNSF15 = S(1.57055634, 0.218987094, 1.50824017, 0.0116507014, 0.0597856897, 132.709339);
constexpr Sellmeier kSF57 = S(1.81651371, 0.428893641, 1.07186278, 0.0143704198, 0.0592801172, 121.419942);
constexpr Sellmeier kNSF57 = S(1.87543831, 0.37375749, 2.30001797, 0.0141749518, 0.0640509927, 177.389795);
// Fused silica, Malitson (1965): C = (0.0684043, 0.1162414, 9.896161 um)^2.
constexpr Sellmeier kSilica = S(0.6961663, 0.4079426, 0.8974794, 0.00467914826, 0.0135120631, 97.9340025);

const std::array kCatalog = {
    // Crowns.
    CatalogGlass{"N-BK7", 1.51680, 64.17, kNBK7, ""},
    CatalogGlass{"BK7", 1.51680, 64.17, kNBK7, "N-BK7"},
    CatalogGlass{"N-BK10", 1.49782, 66.95, kNBK10, ""},
    CatalogGlass{"BK1", 1.51009, 63.46, std::nullopt, ""},
    CatalogGlass{"N-K5", 1.52249, 59.48, kNK5, ""},
    CatalogGlass{"K5", 1.52249, 59.48, kNK5, "N-K5"},
    CatalogGlass{"K7", 1.51112, 60.41, kK7, ""},
    CatalogGlass{"K10", 1.50137, 56.41, kK10, ""},
    CatalogGlass{"N-KF9", 1.52346, 51.54, kNKF9, ""},
    CatalogGlass{"KF9", 1.52341, 51.49, kNKF9, "N-KF9"},
    CatalogGlass{"N-FK5", 1.48749, 70.41, kNFK5, ""},
    CatalogGlass{"FK5", 1.48749, 70.41, kNFK5, "N-FK5"},
    CatalogGlass{"N-FK51A", 1.48656, 84.47, kNFK51A, ""},
    CatalogGlass{"N-PK52A", 1.49700, 81.61, kNPK52A, ""},
    CatalogGlass{"N-PSK3", 1.55232, 63.46, kNPSK3, ""},
    CatalogGlass{"PSK3", 1.55232, 63.46, kNPSK3, "N-PSK3"},
    CatalogGlass{"N-PSK53A", 1.61800, 63.39, kNPSK53A, ""},
    CatalogGlass{"N-BAK1", 1.57250, 57.55, kNBAK1, ""},
    CatalogGlass{"BAK1", 1.57250, 57.55, kNBAK1, "N-BAK1"},
    CatalogGlass{"N-BAK2", 1.53996, 59.71, kNBAK2, ""},
    CatalogGlass{"N-BAK4", 1.56883, 55.98, kNBAK4, ""},
    CatalogGlass{"BAK4", 1.56883, 55.98, kNBAK4, "N-BAK4"},
    CatalogGlass{"N-BALF4", 1.57956, 53.87, kNBALF4, ""},
    CatalogGlass{"N-SK2", 1.60738, 56.65, kNSK2, ""},
    CatalogGlass{"SK2", 1.60738, 56.65, kNSK2, "N-SK2"},
    CatalogGlass{"N-SK4", 1.61272, 58.63, kNSK4, ""},
    CatalogGlass{"SK4", 1.61272, 58.63, kNSK4, "N-SK4"},
    CatalogGlass{"N-SK5", 1.58913, 61.27, kNSK5, ""},
    CatalogGlass{"SK5", 1.58913, 61.27, kNSK5, "N-SK5"},
    CatalogGlass{"N-SK11", 1.56384, 60.80, kNSK11, ""},
    CatalogGlass{"SK11", 1.56384, 60.80, kNSK11, "N-SK11"},
    CatalogGlass{"N-SK14", 1.60311, 60.60, kNSK14, ""},
    CatalogGlass{"SK14", 1.60311, 60.60, kNSK14, "N-SK14"},
    CatalogGlass{"N-SK16", 1.62041, 60.32, kNSK16, ""},
    CatalogGlass{"SK16", 1.62041, 60.33, kNSK16, "N-SK16"},
    CatalogGlass{"N-SSK2", 1.62229, 53.27, kNSSK2, ""},
    CatalogGlass{"N-SSK5", 1.65844, 50.88, kNSSK5, ""},
    CatalogGlass{"N-SSK8", 1.61773, 49.83, kNSSK8, ""},
    CatalogGlass{"SSK4", 1.61765, 55.14, std::nullopt, ""},
    CatalogGlass{"N-LAK8", 1.71300, 53.83, kNLAK8, ""},
    CatalogGlass{"LAK8", 1.71300, 53.83, kNLAK8, "N-LAK8"},
    CatalogGlass{"N-LAK9", 1.69100, 54.71, kNLAK9, ""},
    CatalogGlass{"LAK9", 1.69100, 54.71, kNLAK9, "N-LAK9"},
    CatalogGlass{"N-LAK10", 1.72003, 50.62, kNLAK10, ""},
    CatalogGlass{"LAK10", 1.72000, 50.41, kNLAK10, "N-LAK10"},
    CatalogGlass{"N-LAK12", 1.67790, 55.20, kNLAK12, ""},
    CatalogGlass{"N-LAK14", 1.69680, 55.41, kNLAK14, ""},
    CatalogGlass{"N-LAK22", 1.65113, 55.89, kNLAK22, ""},
    CatalogGlass{"N-LAK33B", 1.75500, 52.30, kNLAK33B, ""},
    // Flints and barium flints.
    CatalogGlass{"N-BAF4", 1.60568, 43.72, kNBAF4, ""},
    CatalogGlass{"BAF4", 1.60562, 43.93, kNBAF4, "N-BAF4"},
    CatalogGlass{"BAF3", 1.58267, 46.47, std::nullopt, ""},
    CatalogGlass{"N-BAF10", 1.67003, 47.11, kNBAF10, ""},
    CatalogGlass{"BAF10", 1.67003, 47.11, kNBAF10, "N-BAF10"},
    CatalogGlass{"N-BAF52", 1.60863, 46.60, kNBAF52, ""},
    CatalogGlass{"N-BASF2", 1.66446, 36.00, kNBASF2, ""},
    CatalogGlass{"N-BASF64", 1.70400, 39.38, kNBASF64, ""},
    CatalogGlass{"N-KZFS4", 1.61336, 44.49, kNKZFS4, ""},
    CatalogGlass{"KZFSN4", 1.61340, 44.29, kNKZFS4, "N-KZFS4"},
    CatalogGlass{"N-KZFS11", 1.63775, 42.41, kNKZFS11, ""},
    CatalogGlass{"N-LAF2", 1.74397, 44.85, kNLAF2, ""},
    CatalogGlass{"LAF2", 1.74400, 44.72, kNLAF2, "N-LAF2"},
    CatalogGlass{"LAF3", 1.71700, 47.96, std::nullopt, ""},
    CatalogGlass{"N-LAF21", 1.78800, 47.49, kNLAF21, ""},
    CatalogGlass{"N-LAF34", 1.77250, 49.62, kNLAF34, ""},
    CatalogGlass{"N-LASF9", 1.85025, 32.17, kNLASF9, ""},
    CatalogGlass{"N-LASF44", 1.80420, 46.50, kNLASF44, ""},
    CatalogGlass{"LLF1", 1.54814, 45.75, kLLF1, ""},
    CatalogGlass{"LF5", 1.58144, 40.85, kLF5, ""},
    CatalogGlass{"F2", 1.62004, 36.37, kF2, ""},
    CatalogGlass{"N-F2", 1.62005, 36.43, kNF2, ""},
    CatalogGlass{"F4", 1.61659, 36.63, std::nullopt, ""},
    CatalogGlass{"F5", 1.60342, 38.03, kF5, ""},
    CatalogGlass{"SF1", 1.71736, 29.51, kSF1, ""},
    CatalogGlass{"N-SF1", 1.71736, 29.62, kNSF1, ""},
    CatalogGlass{"SF2", 1.64769, 33.85, kSF2, ""},
    CatalogGlass{"N-SF2", 1.64769, 33.82, kNSF2, ""},
    CatalogGlass{"SF4", 1.75520, 27.58, kSF4, ""},
    CatalogGlass{"N-SF4", 1.75513, 27.38, kNSF4, ""},
    CatalogGlass{"SF5", 1.67270, 32.21, kSF5, ""},
    CatalogGlass{"N-SF5", 1.67271, 32.25, kNSF5, ""},
    CatalogGlass{"SF6", 1.80518, 25.43, kSF6, ""},
    CatalogGlass{"N-SF6", 1.80518, 25.36, kNSF6, ""},
    CatalogGlass{"N-SF8", 1.68894, 31.31, kNSF8, ""},
    CatalogGlass{"SF8", 1.68893, 31.18, kNSF8, "N-SF8"},
    CatalogGlass{"SF10", 1.72825, 28.41, kSF10, ""},
    CatalogGlass{"N-SF10", 1.72828, 28.53, kNSF10, ""},
    CatalogGlass{"SF11", 1.78472, 25.76, kSF11, ""},
    CatalogGlass{"N-SF11", 1.78472, 25.68, kNSF11, ""},
    CatalogGlass{"N-SF14", 1.76182, 26.53, kNSF14, ""},
    CatalogGlass{"N-SF15", 1.69892, 30.20, kNSF15, ""},
    CatalogGlass{"SF57", 1.84666, 23.83, kSF57, ""},
    CatalogGlass{"N-SF57", 1.84666, 23.78, kNSF57, ""},
    // Not Schott, but in every design program's catalogue.
    CatalogGlass{"F_SILICA", 1.45846, 67.82, kSilica, ""},
};

bool equalIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
         });
}

}  // namespace

std::span<const CatalogGlass> glassCatalog() {
  return kCatalog;
}

std::optional<Medium> findCatalogGlass(std::string_view name) {
  for (const CatalogGlass& g : kCatalog) {
    if (!equalIgnoringCase(g.name, name)) continue;
    Medium m;
    m.nd = g.nd;
    m.vd = g.vd;
    m.glass = std::string(g.name);
    m.sellmeier = g.sellmeier;
    return m;
  }
  return std::nullopt;
}

}  // namespace lensrt
