//! An allocation-free explicit Runge–Kutta pair of order 8 with embedded error estimators of
//! orders 5 and 3 (DOP853), and its continuous extension of order 7, on fixed-size arrays.
//!
//! Dormand & Prince, *High order embedded Runge–Kutta formulae*, J. Comp. Appl. Math. 7
//! (1981); the coefficients, the combined 5th/3rd-order error estimate and the dense output
//! are those of Hairer, Nørsett & Wanner, *Solving Ordinary Differential Equations I*
//! (2nd ed., Springer 1993), §II.5 and §II.6, as published with their code `DOP853`. The
//! eighth-order solution is propagated (local extrapolation). A step costs twelve stages;
//! the derivative at the step's end (the thirteenth evaluation) is the first stage of the
//! next step. Event location re-steps from the step's start with a shorter step, so every
//! event lies on the discrete solution itself; the dense output only seeds that search.

// The coefficients are written with all the digits published (more than an f64 holds), so
// that they can be checked against the source digit by digit.
#![allow(clippy::excessive_precision)]

// Nodes.
const C2: f64 = 0.526_001_519_587_677_318_785_587_544_488e-1;
const C3: f64 = 0.789_002_279_381_515_978_178_381_316_732e-1;
const C4: f64 = 0.118_350_341_907_227_396_726_757_197_510;
const C5: f64 = 0.281_649_658_092_772_603_273_242_802_490;
const C6: f64 = 1.0 / 3.0;
const C7: f64 = 0.25;
const C8: f64 = 4.0 / 13.0;
const C9: f64 = 127.0 / 195.0;
const C10: f64 = 0.6;
const C11: f64 = 6.0 / 7.0;
const C14: f64 = 0.1;
const C15: f64 = 0.2;
const C16: f64 = 7.0 / 9.0;

// Stage coefficients a_ij (the zero ones omitted).
const A21: f64 = 5.260_015_195_876_773_187_855_875_444_88e-2;
const A31: f64 = 1.972_505_698_453_789_945_445_953_291_83e-2;
const A32: f64 = 5.917_517_095_361_369_836_337_859_875_49e-2;
const A41: f64 = 2.958_758_547_680_684_918_168_929_937_75e-2;
const A43: f64 = 8.876_275_643_042_054_754_506_789_813_24e-2;
const A51: f64 = 2.413_651_341_592_666_855_023_697_986_65e-1;
const A53: f64 = -8.845_494_793_282_860_853_448_649_627_17e-1;
const A54: f64 = 9.248_340_032_617_920_031_157_379_665_43e-1;
const A61: f64 = 3.703_703_703_703_703_703_703_703_703_7e-2;
const A64: f64 = 1.708_286_087_294_738_712_796_044_821_73e-1;
const A65: f64 = 1.254_676_875_668_224_250_166_918_141_23e-1;
const A71: f64 = 3.710_937_5e-2;
const A74: f64 = 1.702_522_110_195_440_393_149_780_602_72e-1;
const A75: f64 = 6.021_653_898_045_596_068_502_193_972_83e-2;
const A76: f64 = -1.757_812_5e-2;
const A81: f64 = 3.709_200_011_850_479_271_087_793_198_36e-2;
const A84: f64 = 1.703_839_257_122_399_938_102_140_547_05e-1;
const A85: f64 = 1.072_620_304_463_732_846_518_091_991_68e-1;
const A86: f64 = -1.531_943_774_862_440_175_279_361_582_36e-2;
const A87: f64 = 8.273_789_163_814_022_887_584_737_660_02e-3;
const A91: f64 = 6.241_109_587_160_757_171_144_295_778_12e-1;
const A94: f64 = -3.360_892_629_446_941_294_068_571_098_25;
const A95: f64 = -8.682_193_468_417_260_068_181_898_914_53e-1;
const A96: f64 = 2.759_209_969_944_670_830_494_156_007_97e1;
const A97: f64 = 2.015_406_755_047_789_340_861_867_889_79e1;
const A98: f64 = -4.348_988_418_106_995_884_773_662_551_44e1;
const A101: f64 = 4.776_625_364_382_643_658_904_339_085_27e-1;
const A104: f64 = -2.488_114_619_971_667_641_926_425_864_68;
const A105: f64 = -5.902_908_268_368_429_963_714_464_757_43e-1;
const A106: f64 = 2.123_005_144_818_119_423_472_889_498_97e1;
const A107: f64 = 1.527_923_363_288_242_358_325_969_229_38e1;
const A108: f64 = -3.328_821_096_898_486_291_944_532_655_87e1;
const A109: f64 = -2.033_120_170_850_862_613_582_229_285_93e-2;
const A111: f64 = -9.371_424_300_859_873_257_170_402_165_8e-1;
const A114: f64 = 5.186_372_428_844_063_708_300_238_532_09;
const A115: f64 = 1.091_437_348_996_729_578_185_002_546_54;
const A116: f64 = -8.149_787_010_746_926_125_139_972_673_57;
const A117: f64 = -1.852_006_565_999_695_986_415_661_807_01e1;
const A118: f64 = 2.273_948_709_935_050_428_189_700_567_34e1;
const A119: f64 = 2.493_605_552_679_652_389_870_893_967_62;
const A1110: f64 = -3.046_764_471_898_219_500_382_366_902_2;
const A121: f64 = 2.273_310_147_516_538_207_923_597_684_49;
const A124: f64 = -1.053_449_546_673_725_019_840_666_898_79e1;
const A125: f64 = -2.000_872_058_224_862_499_096_757_184_44;
const A126: f64 = -1.795_893_186_311_879_891_727_659_505_34e1;
const A127: f64 = 2.794_888_452_941_996_005_084_998_088_37e1;
const A128: f64 = -2.858_998_277_135_023_694_740_655_086_74;
const A129: f64 = -8.872_856_933_530_629_544_335_492_892_58;
const A1210: f64 = 1.236_056_717_579_430_306_472_662_015_28e1;
const A1211: f64 = 6.433_927_460_157_635_303_559_704_840_46e-1;

// Eighth-order weights (b2 … b5 are zero).
const B1: f64 = 5.429_373_411_656_876_223_805_357_663_63e-2;
const B6: f64 = 4.450_312_892_752_408_881_441_139_505_66;
const B7: f64 = 1.891_517_899_314_500_383_042_815_990_44;
const B8: f64 = -5.801_203_960_010_584_781_467_211_422_7;
const B9: f64 = 3.111_643_669_578_198_944_089_160_623_7e-1;
const B10: f64 = -1.521_609_496_625_160_785_561_788_068_05e-1;
const B11: f64 = 2.013_654_008_040_303_483_747_765_375_01e-1;
const B12: f64 = 4.471_061_572_777_259_051_768_855_690_43e-2;

// Third-order estimator: b − b̂₃ has these entries at stages 1, 9 and 12 besides b.
const BHH1: f64 = 0.244_094_488_188_976_377_952_755_905_512;
const BHH2: f64 = 0.733_846_688_281_611_857_341_361_741_547;
const BHH3: f64 = 0.220_588_235_294_117_647_058_823_529_412e-1;

// Fifth-order estimator b − b̂₅.
const ER1: f64 = 0.131_200_449_941_948_807_325_010_299_6e-1;
const ER6: f64 = -0.122_515_644_637_620_444_072_056_975_3e1;
const ER7: f64 = -0.495_758_949_657_250_191_521_407_995_2;
const ER8: f64 = 0.166_437_718_245_498_653_696_153_041_5e1;
const ER9: f64 = -0.350_328_848_749_973_681_688_648_729_0;
const ER10: f64 = 0.334_179_118_713_017_479_029_731_884_1;
const ER11: f64 = 0.819_232_064_851_157_124_657_074_261_3e-1;
const ER12: f64 = -0.223_553_078_638_862_952_588_442_784_5e-1;

// Extra stages of the continuous extension.
const A141: f64 = 5.616_750_228_304_795_233_929_092_196_81e-2;
const A147: f64 = 2.535_002_102_166_248_110_887_947_653_33e-1;
const A148: f64 = -2.462_390_374_708_024_899_174_414_754_41e-1;
const A149: f64 = -1.241_914_232_638_163_604_690_101_406_26e-1;
const A1410: f64 = 1.532_917_982_787_656_973_120_632_268_5e-1;
const A1411: f64 = 8.201_052_295_634_689_884_916_666_020_57e-3;
const A1412: f64 = 7.567_897_660_545_699_761_386_035_895_84e-3;
const A1413: f64 = -8.298e-3;
const A151: f64 = 3.183_464_816_350_214_050_607_684_732_61e-2;
const A156: f64 = 2.830_090_967_236_677_552_883_229_614_02e-2;
const A157: f64 = 5.354_198_830_743_856_762_237_973_843_72e-2;
const A158: f64 = -5.492_374_857_139_098_846_465_693_403_06e-2;
const A1511: f64 = -1.083_473_286_972_493_228_585_093_169_94e-4;
const A1512: f64 = 3.825_710_908_356_584_129_549_201_923_23e-4;
const A1513: f64 = -3.404_650_086_874_045_608_029_771_144_92e-4;
const A1514: f64 = 1.413_124_436_746_325_002_780_746_183_66e-1;
const A161: f64 = -4.288_963_015_837_919_234_085_735_386_92e-1;
const A166: f64 = -4.697_621_415_361_163_843_144_494_472_06;
const A167: f64 = 7.683_421_196_062_599_041_842_409_538_78;
const A168: f64 = 4.068_989_818_397_110_079_702_135_543_31;
const A169: f64 = 3.567_271_874_552_811_092_706_695_430_21e-1;
const A1613: f64 = -1.399_024_165_159_014_621_294_180_097_34e-3;
const A1614: f64 = 2.947_514_789_152_772_338_955_627_214_9;
const A1615: f64 = -9.150_958_472_179_870_010_818_701_871_38;

// Dense-output coefficients d_ij for the polynomial coefficients 5 … 8 (stages 1, 6 … 16).
const D4: [f64; 12] = [
    -0.842_893_827_610_901_286_513_534_911_42e1,
    0.566_714_953_519_377_769_625_317_835_90,
    -0.306_894_994_594_989_169_127_973_047_27e1,
    0.238_466_765_651_206_982_877_281_496_80e1,
    0.211_703_458_244_502_827_671_551_499_46e1,
    -0.871_391_583_777_972_992_067_899_074_90,
    0.224_043_743_026_078_827_585_417_716_50e1,
    0.631_578_778_769_468_818_155_702_492_90,
    -0.889_903_364_513_333_108_206_981_174_00e-1,
    0.181_485_055_208_547_272_566_564_049_62e2,
    -0.919_463_239_247_835_540_004_519_844_36e1,
    -0.443_603_638_759_489_396_643_105_720_00e1,
];
const D5: [f64; 12] = [
    0.104_275_086_425_791_346_034_131_510_09e2,
    0.242_283_491_775_258_182_884_301_753_19e3,
    0.165_200_451_717_270_281_985_053_948_87e3,
    -0.374_546_754_722_690_202_795_183_121_52e3,
    -0.221_136_668_531_253_060_362_709_385_78e2,
    0.773_343_266_847_226_383_896_038_988_08e1,
    -0.306_740_847_310_893_981_820_612_136_26e2,
    -0.933_213_052_643_022_787_295_672_217_06e1,
    0.156_972_381_217_708_438_861_310_910_75e2,
    -0.311_394_032_195_651_776_772_828_504_11e2,
    -0.935_292_435_884_447_838_657_138_626_64e1,
    0.358_168_414_863_940_837_524_658_985_40e2,
];
const D6: [f64; 12] = [
    0.199_850_532_420_024_338_209_876_536_17e2,
    -0.387_037_308_749_351_765_551_059_017_42e3,
    -0.189_178_138_195_167_568_828_308_383_28e3,
    0.527_808_159_205_423_649_005_610_166_86e3,
    -0.115_739_025_399_596_301_261_418_711_34e2,
    0.688_123_269_469_630_001_696_669_226_61e1,
    -0.100_060_509_669_108_384_031_838_609_80e1,
    0.777_713_779_805_344_320_928_692_657_40,
    -0.277_820_575_235_350_840_659_320_043_39e1,
    -0.601_966_952_312_641_207_582_673_808_46e2,
    0.843_204_055_066_771_610_181_599_037_84e2,
    0.119_922_911_361_827_893_280_351_300_30e2,
];
const D7: [f64; 12] = [
    -0.256_939_334_627_037_490_033_125_861_29e2,
    -0.154_189_748_690_236_433_740_539_936_27e3,
    -0.231_529_379_176_045_495_675_360_391_09e3,
    0.357_639_117_910_614_123_782_853_499_10e3,
    0.934_053_241_836_243_100_039_076_917_04e2,
    -0.374_583_231_364_516_331_568_751_393_51e2,
    0.104_099_649_508_962_300_451_472_461_84e3,
    0.298_402_934_266_605_031_233_443_635_79e2,
    -0.435_334_565_900_111_437_544_321_750_58e2,
    0.963_245_539_591_882_829_483_949_506_00e2,
    -0.391_772_616_756_154_391_652_314_861_72e2,
    -0.149_726_836_257_985_625_814_221_252_76e3,
];

#[inline(always)]
fn comb<const N: usize>(y: &[f64; N], h: f64, terms: &[(f64, &[f64; N])]) -> [f64; N] {
    let mut out = [0.0; N];
    for (c, k) in terms {
        for i in 0..N {
            out[i] += c * k[i];
        }
    }
    for i in 0..N {
        out[i] = y[i] + h * out[i];
    }
    out
}

/// One DOP853 step: the eighth-order solution `y`, the two error estimates (of orders 5 and
/// 3, already multiplied by `h`) and the stages, kept for the continuous extension.
#[derive(Clone, Copy)]
pub(crate) struct Step<const N: usize> {
    /// The eighth-order solution at `x + h`.
    pub y: [f64; N],
    /// `h (b − b̂₅)·k`.
    pub err5: [f64; N],
    /// `h (b − b̂₃)·k`.
    pub err3: [f64; N],
    /// Stages 1 and 6 … 12 (stages 2 … 5 have zero weight in `b` and in the extension).
    k: [[f64; N]; 8],
}

/// One DOP853 step of size `h` from `(x, y)` with derivative `k1 = f(x, y)`.
#[inline]
pub(crate) fn dop853_step<const N: usize>(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    x: f64,
    y: &[f64; N],
    k1: &[f64; N],
    h: f64,
) -> Step<N> {
    let k2 = f(x + C2 * h, &comb(y, h, &[(A21, k1)]));
    let k3 = f(x + C3 * h, &comb(y, h, &[(A31, k1), (A32, &k2)]));
    let k4 = f(x + C4 * h, &comb(y, h, &[(A41, k1), (A43, &k3)]));
    let k5 = f(
        x + C5 * h,
        &comb(y, h, &[(A51, k1), (A53, &k3), (A54, &k4)]),
    );
    let k6 = f(
        x + C6 * h,
        &comb(y, h, &[(A61, k1), (A64, &k4), (A65, &k5)]),
    );
    let k7 = f(
        x + C7 * h,
        &comb(y, h, &[(A71, k1), (A74, &k4), (A75, &k5), (A76, &k6)]),
    );
    let k8 = f(
        x + C8 * h,
        &comb(
            y,
            h,
            &[(A81, k1), (A84, &k4), (A85, &k5), (A86, &k6), (A87, &k7)],
        ),
    );
    let k9 = f(
        x + C9 * h,
        &comb(
            y,
            h,
            &[
                (A91, k1),
                (A94, &k4),
                (A95, &k5),
                (A96, &k6),
                (A97, &k7),
                (A98, &k8),
            ],
        ),
    );
    let k10 = f(
        x + C10 * h,
        &comb(
            y,
            h,
            &[
                (A101, k1),
                (A104, &k4),
                (A105, &k5),
                (A106, &k6),
                (A107, &k7),
                (A108, &k8),
                (A109, &k9),
            ],
        ),
    );
    let k11 = f(
        x + C11 * h,
        &comb(
            y,
            h,
            &[
                (A111, k1),
                (A114, &k4),
                (A115, &k5),
                (A116, &k6),
                (A117, &k7),
                (A118, &k8),
                (A119, &k9),
                (A1110, &k10),
            ],
        ),
    );
    let k12 = f(
        x + h,
        &comb(
            y,
            h,
            &[
                (A121, k1),
                (A124, &k4),
                (A125, &k5),
                (A126, &k6),
                (A127, &k7),
                (A128, &k8),
                (A129, &k9),
                (A1210, &k10),
                (A1211, &k11),
            ],
        ),
    );
    let mut out = Step {
        y: [0.0; N],
        err5: [0.0; N],
        err3: [0.0; N],
        k: [*k1, k6, k7, k8, k9, k10, k11, k12],
    };
    for i in 0..N {
        let inc = B1 * k1[i]
            + B6 * k6[i]
            + B7 * k7[i]
            + B8 * k8[i]
            + B9 * k9[i]
            + B10 * k10[i]
            + B11 * k11[i]
            + B12 * k12[i];
        out.y[i] = y[i] + h * inc;
        out.err3[i] = h * (inc - BHH1 * k1[i] - BHH2 * k9[i] - BHH3 * k12[i]);
        out.err5[i] = h
            * (ER1 * k1[i]
                + ER6 * k6[i]
                + ER7 * k7[i]
                + ER8 * k8[i]
                + ER9 * k9[i]
                + ER10 * k10[i]
                + ER11 * k11[i]
                + ER12 * k12[i]);
    }
    out
}

/// The error measure of Hairer's `DOP853` in the maximum norm: with `e₅`, `e₃` the scaled
/// largest components of the two estimates, `e₅² / √(e₅² + 0.01 e₃²)` (a fifth-order
/// estimate that behaves like an eighth-order one as `h → 0`). `scale(i)` is the
/// per-component tolerance. NaN — a step to reject — when the step's result or an error
/// ratio is not a number or not finite (a maximum would pass over a NaN, and a step that
/// overflowed has an infinite scale: without this test it could be accepted).
#[inline]
pub(crate) fn error_measure<const N: usize>(step: &Step<N>, scale: impl Fn(usize) -> f64) -> f64 {
    let (mut e5, mut e3) = (0.0f64, 0.0f64);
    for i in 0..N {
        let s = scale(i);
        let (r5, r3) = ((step.err5[i] / s).abs(), (step.err3[i] / s).abs());
        if !(step.y[i].is_finite() && r5.is_finite() && r3.is_finite()) {
            return f64::NAN;
        }
        e5 = e5.max(r5);
        e3 = e3.max(r3);
    }
    let den = e5 * e5 + 0.01 * e3 * e3;
    if den > 0.0 {
        e5 * e5 / den.sqrt()
    } else if den == 0.0 {
        0.0
    } else {
        f64::NAN
    }
}

/// A step's continuous extension: the state at a fraction `θ ∈ [0, 1]` of the step.
pub(crate) trait Interpolant<const N: usize> {
    /// The state at the fraction `theta` of the step.
    fn at(&self, theta: f64) -> [f64; N];
}

impl<const N: usize> Interpolant<N> for Dense<N> {
    #[inline]
    fn at(&self, theta: f64) -> [f64; N] {
        Dense::at(self, theta)
    }
}

/// The seventh-order continuous extension of one accepted step (three more stages).
pub(crate) struct Dense<const N: usize> {
    r: [[f64; N]; 8],
}

impl<const N: usize> Dense<N> {
    /// Build the extension of `step` (taken from `(x, y0)` with size `h`), given
    /// `k13 = f(x + h, step.y)`.
    pub(crate) fn new(
        f: &impl Fn(f64, &[f64; N]) -> [f64; N],
        x: f64,
        y0: &[f64; N],
        step: &Step<N>,
        k13: &[f64; N],
        h: f64,
    ) -> Self {
        let [k1, k6, k7, k8, k9, k10, k11, k12] = &step.k;
        let k14 = f(
            x + C14 * h,
            &comb(
                y0,
                h,
                &[
                    (A141, k1),
                    (A147, k7),
                    (A148, k8),
                    (A149, k9),
                    (A1410, k10),
                    (A1411, k11),
                    (A1412, k12),
                    (A1413, k13),
                ],
            ),
        );
        let k15 = f(
            x + C15 * h,
            &comb(
                y0,
                h,
                &[
                    (A151, k1),
                    (A156, k6),
                    (A157, k7),
                    (A158, k8),
                    (A1511, k11),
                    (A1512, k12),
                    (A1513, k13),
                    (A1514, &k14),
                ],
            ),
        );
        let k16 = f(
            x + C16 * h,
            &comb(
                y0,
                h,
                &[
                    (A161, k1),
                    (A166, k6),
                    (A167, k7),
                    (A168, k8),
                    (A169, k9),
                    (A1613, k13),
                    (A1614, &k14),
                    (A1615, &k15),
                ],
            ),
        );
        let ks: [&[f64; N]; 12] = [k1, k6, k7, k8, k9, k10, k11, k12, k13, &k14, &k15, &k16];
        let mut r = [[0.0; N]; 8];
        for i in 0..N {
            let diff = step.y[i] - y0[i];
            let bspl = h * k1[i] - diff;
            r[0][i] = y0[i];
            r[1][i] = diff;
            r[2][i] = bspl;
            r[3][i] = diff - h * k13[i] - bspl;
            for (row, d) in [&D4, &D5, &D6, &D7].iter().enumerate() {
                let mut s = 0.0;
                for (dj, kj) in d.iter().zip(ks.iter()) {
                    s += dj * kj[i];
                }
                r[4 + row][i] = h * s;
            }
        }
        Dense { r }
    }

    /// The interpolated state at the fraction `theta ∈ [0, 1]` of the step.
    pub(crate) fn at(&self, theta: f64) -> [f64; N] {
        let s = theta;
        let s1 = 1.0 - s;
        let r = &self.r;
        let mut out = [0.0; N];
        for i in 0..N {
            out[i] = r[0][i]
                + s * (r[1][i]
                    + s1 * (r[2][i]
                        + s * (r[3][i]
                            + s1 * (r[4][i] + s * (r[5][i] + s1 * (r[6][i] + s * r[7][i]))))));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // y' = y cos x, y(0) = 1: y = exp(sin x).
    fn f(x: f64, y: &[f64; 1]) -> [f64; 1] {
        [y[0] * x.cos()]
    }

    fn run(n: usize) -> f64 {
        let h = 2.0 / n as f64;
        let (mut x, mut y) = (0.0, [1.0]);
        for _ in 0..n {
            let s = dop853_step(&f, x, &y, &f(x, &y), h);
            y = s.y;
            x += h;
        }
        (y[0] - 2f64.sin().exp()).abs()
    }

    #[test]
    fn tableau_rows_sum_to_their_nodes() {
        let rows: [(f64, &[f64]); 14] = [
            (C2, &[A21]),
            (C3, &[A31, A32]),
            (C4, &[A41, A43]),
            (C5, &[A51, A53, A54]),
            (C6, &[A61, A64, A65]),
            (C7, &[A71, A74, A75, A76]),
            (C8, &[A81, A84, A85, A86, A87]),
            (C9, &[A91, A94, A95, A96, A97, A98]),
            (C10, &[A101, A104, A105, A106, A107, A108, A109]),
            (C11, &[A111, A114, A115, A116, A117, A118, A119, A1110]),
            (
                1.0,
                &[A121, A124, A125, A126, A127, A128, A129, A1210, A1211],
            ),
            (C14, &[A141, A147, A148, A149, A1410, A1411, A1412, A1413]),
            (C15, &[A151, A156, A157, A158, A1511, A1512, A1513, A1514]),
            (C16, &[A161, A166, A167, A168, A169, A1613, A1614, A1615]),
        ];
        for (c, a) in rows {
            let s: f64 = a.iter().sum();
            assert!((s - c).abs() < 1e-14, "row sum {s} vs node {c}");
        }
        let b = B1 + B6 + B7 + B8 + B9 + B10 + B11 + B12;
        assert!((b - 1.0).abs() < 1e-14);
        let er = ER1 + ER6 + ER7 + ER8 + ER9 + ER10 + ER11 + ER12;
        assert!(
            er.abs() < 1e-14,
            "the fifth-order estimator is consistent: {er}"
        );
        assert!((BHH1 + BHH2 + BHH3 - 1.0).abs() < 1e-14);
    }

    #[test]
    fn eighth_order_on_a_smooth_problem() {
        let (e1, e2) = (run(8), run(16));
        let order = (e1 / e2).log2();
        assert!(
            order > 7.5 && order < 9.0,
            "observed order {order} ({e1:e}, {e2:e})"
        );
    }

    #[test]
    fn estimators_vanish_at_least_like_their_orders() {
        // One step from x = 0.3: the estimates b − b̂₅ and b − b̂₃ are O(h⁶) and O(h⁴) at
        // least (on this scalar problem the leading term of the fifth-order one happens to
        // vanish, so it shrinks faster).
        let y0 = [0.3f64.sin().exp()];
        let k = f(0.3, &y0);
        let a = dop853_step(&f, 0.3, &y0, &k, 0.2);
        let b = dop853_step(&f, 0.3, &y0, &k, 0.1);
        let o5 = (a.err5[0] / b.err5[0]).abs().log2();
        let o3 = (a.err3[0] / b.err3[0]).abs().log2();
        assert!(o5 > 5.5, "fifth-order estimator: {o5}");
        assert!(o3 > 3.5 && o3 < 4.6, "third-order estimator: {o3}");
    }

    #[test]
    fn continuous_extension_has_order_seven() {
        let err = |h: f64| {
            let (x, y0) = (0.3, [0.3f64.sin().exp()]);
            let s = dop853_step(&f, x, &y0, &f(x, &y0), h);
            let d = Dense::new(&f, x, &y0, &s, &f(x + h, &s.y), h);
            [0.25, 0.5, 0.8]
                .iter()
                .map(|&t| (d.at(t)[0] - (x + t * h).sin().exp()).abs())
                .fold(0.0f64, f64::max)
        };
        let (e1, e2) = (err(0.4), err(0.2));
        // Local error of a seventh-order extension: O(h⁸).
        let order = (e1 / e2).log2();
        assert!(
            order > 7.3 && order < 9.2,
            "local order {order} ({e1:e}, {e2:e})"
        );
        let s = dop853_step(&f, 0.0, &[1.0], &f(0.0, &[1.0]), 0.3);
        let d = Dense::new(&f, 0.0, &[1.0], &s, &f(0.3, &s.y), 0.3);
        assert_eq!(d.at(0.0)[0], 1.0);
        assert!((d.at(1.0)[0] - s.y[0]).abs() <= 1e-15);
    }
}
