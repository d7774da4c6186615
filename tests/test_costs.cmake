# Read by ctest after the gtest cases are listed (tests/CMakeLists.txt): roughly the seconds each
# long case takes on a 2-core machine, as its COST. `ctest -j` starts the costliest tests first;
# on a fresh clone it has no timings of its own (Testing/Temporary/CTestCostData.txt), and a long
# test started last would run alone at the end. tests/cli/CMakeLists.txt gives the CLI tests'.
set(momentbench_test_costs
  SolveDistribution.RoundedMomentsOfNarrowKernelsAreNeverInfeasible 46
  TechniqueAudit.NoTechniqueClaimsMoreThanItDelivers 36
  Verify.SixMomentsPassOnTheWitnessAndAreNeverUndefined 23
  Screening.StandardErrorsAreCalibratedOverCandidatesAndSeeds 21
  Screening.ScreenedTopKIsTheExactTopK 21
  LpBackends.NarrowKernelsAgreeWithTheExactLpTheyWereGiven 21
  Sweep.DefaultDatasetLeavesAtMostTwoLpsUnstable 13
  LpBackends.AgreeOnOneHundredThousandRandomInstancesAcrossTheCatalog 10
  VerifyContinuous.ExactClosedFormsPassAndABrokenOneFails 8
  Oit.MboitTrigIsNeverBelowTheSharpBoundOnTheCircle 8
  LpBackends.OursAgreesWithTheExactRationalArbiter 8
  SoftTechniques.BitIdenticalForAnyThreadCount 8
  SolveDistribution.RawMomentsOfNarrowKernelsReportTheRangeTheirRoundingAllows 6
  Fuzz.ConfigReaderOnlyEverRefusesWithAMessage 6
  Oit.LpBoundsHoldAndMboitIsTheLpOnR 5
  Fuzz.SceneReaderOnlyEverRefusesWithAMessage 4
  SoftTechniques.PcssOfAHalfPlaneIsNearerTheAreaLightThanTheHardShadow 4
  SoftTechniques.UmbraUnderTheSlabAndLightFarFromIt 4
  Verify.ExactClosedFormsMatchTheLpAndConvergeAsTheGridRefines 3
  CameraViews.AnAreaLightsShadowIsTheLightViewsAtTheSameTexel 3
  SoftTechniques.LpFinalStepIsAtLeastHamburgersBoundAndEqualOnTwoDepths 3
  AreaLight.HalfPlanePenumbraFollowsTheDiskSegment 3
  Verify.AWrongSolverIsCaughtTooLowAndTooHigh 3
  Oit.MboitPower6IsTheLpOnR 3)
while(momentbench_test_costs)
  list(POP_FRONT momentbench_test_costs name cost)
  # A renamed case is no error here: it only loses its place at the front.
  list(FIND momentbench_tests_TESTS "${name}" index)  # (ctest reads this without IN_LIST)
  if(index GREATER -1)
    set_tests_properties("${name}" PROPERTIES COST ${cost})
  endif()
endwhile()
