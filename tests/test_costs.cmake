# Read by ctest after the gtest cases are listed (tests/CMakeLists.txt): the seconds each long
# case takes on an idle 2-core machine, as its COST. `ctest -j` starts the costliest tests first;
# on a fresh clone it has no timings of its own (Testing/Temporary/CTestCostData.txt), and a long
# test started last would run alone at the end. tests/cli/CMakeLists.txt gives the CLI tests'.
set(momentbench_test_costs
  SolveDistribution.RoundedMomentsOfNarrowKernelsAreNeverInfeasible 51
  Screening.ScreenedTopKIsTheExactTopK 45
  VerifyContinuous.ExactClosedFormsPassAndABrokenOneFails 31
  TechniqueAudit.NoTechniqueClaimsMoreThanItDelivers 30
  Screening.StandardErrorsAreCalibratedOverCandidatesAndSeeds 23
  Oit.LpBoundsHoldAndMboitIsTheLpOnR 20
  Oit.MboitPower6IsTheLpOnR 19
  Verify.SixMomentsPassOnTheWitnessAndAreNeverUndefined 10
  LpBackends.NarrowKernelsAgreeWithTheExactLpTheyWereGiven 8
  Sweep.DefaultDatasetLeavesAtMostTwoLpsUnstable 8
  SolveDistribution.RawMomentsOfNarrowKernelsReportTheRangeTheirRoundingAllows 7
  SoftTechniques.BitIdenticalForAnyThreadCount 6
  SoftTechniques.PcssOfAHalfPlaneIsNearerTheAreaLightThanTheHardShadow 6
  Oit.MboitTrigIsNeverBelowTheSharpBoundOnTheCircle 5
  Protocol.LonePlaneAtAnySlopeIsLitByEveryTechnique 5
  CameraViews.AnAreaLightsShadowIsTheLightViewsAtTheSameTexel 5
  SoftTechniques.UmbraUnderTheSlabAndLightFarFromIt 4
  OitVerify.MboitRowsPassAgainstTheLp 4
  LpBackends.AgreeOnOneHundredThousandRandomInstancesAcrossTheCatalog 4
  SoftTechniques.LpFinalStepIsAtLeastHamburgersBoundAndEqualOnTwoDepths 4
  LpBackends.OursAgreesWithTheExactRationalArbiter 3
  AreaLight.HalfPlanePenumbraFollowsTheDiskSegment 3
  Fuzz.ConfigReaderOnlyEverRefusesWithAMessage 3)
while(momentbench_test_costs)
  list(POP_FRONT momentbench_test_costs name cost)
  # A renamed case is no error here: it only loses its place at the front.
  list(FIND momentbench_tests_TESTS "${name}" index)  # (ctest reads this without IN_LIST)
  if(index GREATER -1)
    set_tests_properties("${name}" PROPERTIES COST ${cost})
  endif()
endwhile()
