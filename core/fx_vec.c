/* SPDX-License-Identifier: MIT */
/* fx_vec: the vector operations too large to inline. */
#include "fx_vec.h"
#include "fx_rsqrt.h"

fx_t fx_v3_dot(fx_vec3 a, fx_vec3 b)
{
    /* Each exact product is at most 2^62 in magnitude; three of them can
     * overflow int64. Halve each (floor), keep the dropped low bits apart,
     * and fold them back in when rounding. */
    int64_t p0 = fx_imul64(a.x, b.x), p1 = fx_imul64(a.y, b.y);
    int64_t p2 = fx_imul64(a.z, b.z);
    int64_t half = (p0 >> 1) + (p1 >> 1) + (p2 >> 1);
    int64_t lows = (p0 & 1) + (p1 & 1) + (p2 & 1);
#if RT_ACCURACY == 0
    /* floor((2*half + lows) / 2^16) = floor((half + lows / 2) / 2^15), and
     * a half cannot carry an integer past a multiple of 2^15. */
    return fx_sat64((half + (lows >> 1)) >> 15);
#elif RT_ACCURACY == 1
    /* round((2*half + lows) / 2^16) = floor((half + (lows + 2^15) / 2) / 2^15) */
    return fx_sat64((half + ((lows + 0x8000) >> 1)) >> 15);
#else
    /* The sum is 2h + b: its quotient q = h >> 15 and the 16 bits below,
     * 2 (h mod 2^15) + b, decide the rounding, ties to even. */
    int64_t h = half + (lows >> 1);
    int64_t q = h >> 15;
    int32_t frac = (int32_t)(2 * (h & 0x7FFF) + (lows & 1));
    return fx_sat64(q + (frac > 0x8000 || (frac == 0x8000 && (q & 1))));
#endif
}

uint64_t fx_v3_len2_q32(fx_vec3 a)
{
    int64_t x = a.x, y = a.y, z = a.z;
    return (uint64_t)(x * x) + (uint64_t)(y * y) + (uint64_t)(z * z);
}

fx_vec3 fx_v3_cross(fx_vec3 a, fx_vec3 b)
{
    /* a.y*b.z - a.z*b.y: each product is below 2^62, the difference below
     * 2^63, so int64 holds it exactly. */
    int64_t x = fx_imul64(a.y, b.z) - fx_imul64(a.z, b.y);
    int64_t y = fx_imul64(a.z, b.x) - fx_imul64(a.x, b.z);
    int64_t z = fx_imul64(a.x, b.y) - fx_imul64(a.y, b.x);
    return fx_v3(fx_from_q32(x), fx_from_q32(y), fx_from_q32(z));
}

fx_t fx_v3_length(fx_vec3 a)
{
    uint32_t l = fx_sqrt_q32(fx_v3_len2_q32(a));
    return l > (uint32_t)FX_MAX ? FX_MAX : (fx_t)l;
}

#if RT_ACCURACY == 0
/* 2^46 / sqrt(m) at m = (128 + i) * 2^23, i = 0..384, each lowered by half
 * the gap between chord and curve there (h^2 g''(x) / 16 with x = m / 2^32,
 * h = 1/512, g(x) = x^-1/2): linear interpolation between neighbours is
 * then within 3 * 10^-6 of 2^46 / sqrt(m), above or below, for every m. */
static const uint32_t rsqrt_lin[385] = {
    2147477504, 2139137849, 2130894604, 2122745927, 2114690024, 2106725146,
    2098849593, 2091061708, 2083359875, 2075742523, 2068208117, 2060755163,
    2053382204, 2046087820, 2038870624, 2031729265, 2024662423, 2017668812,
    2010747176, 2003896289, 1997114953, 1990401999, 1983756287, 1977176700,
    1970662150, 1964211572, 1957823926, 1951498195, 1945233386, 1939028526,
    1932882666, 1926794877, 1920764250, 1914789896, 1908870944, 1903006545,
    1897195865, 1891438090, 1885732420, 1880078075, 1874474291, 1868920317,
    1863415421, 1857958884, 1852550002, 1847188085, 1841872458, 1836602458,
    1831377437, 1826196758, 1821059797, 1815965944, 1810914598, 1805905171,
    1800937088, 1796009782, 1791122698, 1786275293, 1781467033, 1776697393,
    1771965858, 1767271926, 1762615099, 1757994892, 1753410827, 1748862435,
    1744349257, 1739870840, 1735426740, 1731016521, 1726639755, 1722296021,
    1717984905, 1713706002, 1709458912, 1705243243, 1701058610, 1696904633,
    1692780940, 1688687165, 1684622948, 1680587935, 1676581777, 1672604133,
    1668654665, 1664733043, 1660838942, 1656972040, 1653132022, 1649318579,
    1645531405, 1641770200, 1638034669, 1634324521, 1630639469, 1626979233,
    1623343534, 1619732100, 1616144663, 1612580956, 1609040721, 1605523701,
    1602029642, 1598558297, 1595109420, 1591682769, 1588278108, 1584895202,
    1581533820, 1578193735, 1574874723, 1571576563, 1568299038, 1565041934,
    1561805039, 1558588146, 1555391049, 1552213546, 1549055437, 1545916527,
    1542796621, 1539695528, 1536613061, 1533549033, 1530503262, 1527475566,
    1524465768, 1521473691, 1518499164, 1515542014, 1512602074, 1509679177,
    1506773159, 1503883858, 1501011115, 1498154772, 1495314673, 1492490665,
    1489682598, 1486890320, 1484113686, 1481352549, 1478606766, 1475876195,
    1473160696, 1470460131, 1467774363, 1465103259, 1462446684, 1459804508,
    1457176602, 1454562836, 1451963086, 1449377225, 1446805131, 1444246682,
    1441701758, 1439170240, 1436652011, 1434146954, 1431654956, 1429175904,
    1426709685, 1424256190, 1421815309, 1419386934, 1416970960, 1414567281,
    1412175792, 1409796393, 1407428980, 1405073453, 1402729714, 1400397665,
    1398077208, 1395768248, 1393470690, 1391184441, 1388909408, 1386645500,
    1384392627, 1382150698, 1379919627, 1377699324, 1375489705, 1373290684,
    1371102175, 1368924097, 1366756365, 1364598900, 1362451618, 1360314442,
    1358187291, 1356070089, 1353962756, 1351865218, 1349777397, 1347699221,
    1345630613, 1343571502, 1341521815, 1339481480, 1337450426, 1335428584,
    1333415883, 1331412255, 1329417632, 1327431947, 1325455133, 1323487125,
    1321527857, 1319577264, 1317635283, 1315701851, 1313776906, 1311860384,
    1309952226, 1308052369, 1306160756, 1304277325, 1302402018, 1300534777,
    1298675544, 1296824262, 1294980874, 1293145326, 1291317560, 1289497523,
    1287685160, 1285880418, 1284083242, 1282293581, 1280511382, 1278736593,
    1276969163, 1275209042, 1273456179, 1271710524, 1269972029, 1268240644,
    1266516321, 1264799012, 1263088670, 1261385248, 1259688699, 1257998978,
    1256316037, 1254639833, 1252970321, 1251307455, 1249651193, 1248001490,
    1246358303, 1244721589, 1243091307, 1241467414, 1239849868, 1238238629,
    1236633654, 1235034905, 1233442340, 1231855921, 1230275607, 1228701359,
    1227133139, 1225570908, 1224014629, 1222464263, 1220919774, 1219381124,
    1217848277, 1216321195, 1214799844, 1213284187, 1211774190, 1210269816,
    1208771031, 1207277800, 1205790090, 1204307866, 1202831095, 1201359743,
    1199893777, 1198433165, 1196977874, 1195527871, 1194083126, 1192643605,
    1191209278, 1189780114, 1188356081, 1186937150, 1185523289, 1184114468,
    1182710658, 1181311829, 1179917952, 1178528997, 1177144936, 1175765740,
    1174391380, 1173021828, 1171657057, 1170297038, 1168941744, 1167591148,
    1166245222, 1164903940, 1163567276, 1162235202, 1160907693, 1159584722,
    1158266264, 1156952293, 1155642783, 1154337710, 1153037049, 1151740774,
    1150448862, 1149161287, 1147878025, 1146599053, 1145324347, 1144053883,
    1142787637, 1141525586, 1140267707, 1139013978, 1137764375, 1136518875,
    1135277457, 1134040098, 1132806777, 1131577470, 1130352157, 1129130815,
    1127913424, 1126699962, 1125490409, 1124284742, 1123082942, 1121884987,
    1120690858, 1119500534, 1118313995, 1117131220, 1115952190, 1114776886,
    1113605287, 1112437375, 1111273129, 1110112531, 1108955562, 1107802202,
    1106652434, 1105506239, 1104363597, 1103224491, 1102088903, 1100956815,
    1099828208, 1098703064, 1097581367, 1096463098, 1095348240, 1094236777,
    1093128689, 1092023961, 1090922576, 1089824517, 1088729766, 1087638309,
    1086550127, 1085465205, 1084383526, 1083305074, 1082229834, 1081157789,
    1080088924, 1079023222, 1077960669, 1076901249, 1075844946, 1074791746,
    1073741632
};

/* About 2^46 / sqrt(m) for m in [2^30, 2^32), in (2^30, 2^31), by linear
 * interpolation (no 64-bit product: cheap on Cortex-M0 too). */
static inline uint32_t rsqrt_fast(uint32_t m)
{
    uint32_t i = (m >> 23) - 128, f = (m >> 7) & 0xFFFFu;
    uint32_t d = (rsqrt_lin[i] - rsqrt_lin[i + 1]) >> 8; /* < 2^15 */
    return rsqrt_lin[i] - ((d * f) >> 8);
}

/* round(b * R / 2^45), ties toward +infinity. */
static inline fx_t unit_fast(int32_t b, uint32_t r)
{
    int32_t hi = (int32_t)(((int64_t)b * (int32_t)r) >> 32);
    return (hi + 0x1000) >> 13;
}

#endif


#if RT_ACCURACY == 1
/* round(b * R / 2^44), ties toward +infinity: the high word of the exact
 * product, then 12 more bits. */
static inline fx_t unit_component(int32_t b, int32_t r)
{
    int32_t hi = (int32_t)((fx_imul64(b, r)) >> 32);
    return (hi + 0x800) >> 12;
}
#endif

#if RT_ACCURACY == 2

/* hi:lo = a * b, exact, from four 32-bit products. */
static void mul_128(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    *lo = (mid << 32) | (uint32_t)p00;
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

/* 1 if |a| / sqrt(len2) >= (n + 1/2) / 2^16, decided on exact integers:
 * (2^17 |a|)^2 >= (2n + 1)^2 len2, both sides below 2^98. */
static int past_half(uint32_t ua, uint32_t n, uint64_t len2)
{
    uint64_t lh, ll, rh, rl, a2 = fx_umul64(ua, ua); /* <= 2^62 */
    uint64_t k = 2 * (uint64_t)n + 1;
    lh = a2 >> 30; /* a2 * 2^34 */
    ll = a2 << 34;
    mul_128(k * k, len2, &rh, &rl);
    return lh > rh || (lh == rh && ll >= rl);
}

/* One component, correctly rounded: b * R / 2^45 (R = rsqrt_q30) is
 * within 2^-13 ulp of a / |a| (from R's 2^-30, m's dropped low word and
 * the halving of b), so the 13 bits of its high word below the ulp settle
 * the rounding unless they are within 4 / 2^13 ulp of the half; then the
 * exact test decides. */
static inline fx_t unit_exact(fx_t a, int32_t b, uint32_t r, uint64_t len2)
{
    uint32_t ub = b < 0 ? 0u - (uint32_t)b : (uint32_t)b;
    uint32_t hi = (uint32_t)((fx_umul64(ub, r)) >> 32); /* < 2^30 */
    uint32_t n = hi >> 13, w = hi & 0x1FFFu;
    if (w - (0x1000u - 4u) <= 8u)
        n += (uint32_t)past_half(a < 0 ? 0u - (uint32_t)a : (uint32_t)a, n,
                                 len2);
    else
        n += w >> 12;
    return a < 0 ? -(fx_t)n : (fx_t)n;
}
#endif

fx_vec3 fx_v3_normalize(fx_vec3 a)
{
    uint64_t len2 = fx_v3_len2_q32(a);
    uint32_t hi = (uint32_t)(len2 >> 32), lo = (uint32_t)len2, m;
    int sh, z;
    /* Scale |a|^2 by 4^j into X in [2^62, 2^64) and keep its top word
     * m = X / 2^32 (30-32 significant bits). Scale a by 2^(j-1), so each
     * |b| <= sqrt(X) / 2 < 2^31; for j = 0 that is a halving, which drops
     * at most 2^-31 of the length. Then b / sqrt(X / 4) is the unit
     * component. Shifting the two words apart avoids a 64-bit shift. */
    if (hi == 0) {
        if (lo == 0)
            return fx_v3(0, 0, 0);
        z = fx_clz32(lo) & ~1;
        m = lo << z;
        sh = 15 + z / 2;
    } else {
        z = fx_clz32(hi) & ~1;
        m = z ? (hi << z) | (lo >> (32 - z)) : hi;
        sh = z / 2 - 1;
    }
    int32_t bx, by, bz;
    if (sh >= 0) {
        /* |a| * 2^sh < 2^31, so the unsigned shift is the exact value. */
        bx = (int32_t)((uint32_t)a.x << sh);
        by = (int32_t)((uint32_t)a.y << sh);
        bz = (int32_t)((uint32_t)a.z << sh);
    } else {
        bx = a.x >> 1;
        by = a.y >> 1;
        bz = a.z >> 1;
    }
#if RT_ACCURACY == 0
    /* u = b * (2^46 / sqrt(m)) / 2^45, with R within 3 * 10^-6 either way:
     * each component within 0.7 ulp, and |u| at most 0.2 ulp past 1
     * before rounding, so never past 1 after. */
    uint32_t r = rsqrt_fast(m);
    return fx_v3(unit_fast(bx, r), unit_fast(by, r), unit_fast(bz, r));
#else
    /* u = b * 2^17 / sqrt(m * 2^32) = b * (2^45 / sqrt(m)) / 2^44. R is
     * an underestimate by at most 2^-20, so |u| never rounds past 1 and
     * each component is within 0.5 + 2^-4 ulp of the truth. */
    int32_t r = fx_rsqrt_q29(m);
#endif
#if RT_ACCURACY == 1
    return fx_v3(unit_component(bx, r), unit_component(by, r),
                 unit_component(bz, r));
#elif RT_ACCURACY == 2
    uint32_t r46 = fx_rsqrt_q30(m, r);
    return fx_v3(unit_exact(a.x, bx, r46, len2),
                 unit_exact(a.y, by, r46, len2),
                 unit_exact(a.z, bz, r46, len2));
#endif
}

/* Unit vector along an exact 64-bit vector (for normals from cross
 * products of tiny edges, which would round to zero in Q16.16). */
static fx_vec3 norm64(int64_t x, int64_t y, int64_t z)
{
    while (x > FX_MAX / 2 || x < FX_MIN / 2 || y > FX_MAX / 2 ||
           y < FX_MIN / 2 || z > FX_MAX / 2 || z < FX_MIN / 2) {
        x /= 2;
        y /= 2;
        z /= 2;
    }
    return fx_v3_normalize(fx_v3((fx_t)x, (fx_t)y, (fx_t)z));
}

fx_vec3 fx_v3_cross_unit(fx_vec3 a, fx_vec3 b)
{
    return norm64(fx_imul64(a.y, b.z) - fx_imul64(a.z, b.y),
                  fx_imul64(a.z, b.x) - fx_imul64(a.x, b.z),
                  fx_imul64(a.x, b.y) - fx_imul64(a.y, b.x));
}
