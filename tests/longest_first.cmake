# The GoogleTest cases over half a minute, with their durations in seconds as measured here
# (ctest -j2, 2 cores), so that ctest starts the costliest first: a fresh build tree has no costs
# of its own, and in declaration order the longest (the batches, the study) would start last and
# run alone on one core. Included after the cases are discovered; the other long tests carry
# their COST where tests/CMakeLists.txt declares them.
set(raven_longest_tests
  StudyCli.TheExampleFindsTheDegradedSchemeWorseWithEightVirtualParticipants 250
  PegTransferBatch.TheGraspAssistPinsEveryRingWholeOnTheNominalAndTwentyRandomisedScenes 286
  PegTransferBatch.OnTheMotorTwinNineteenOfTwentyRandomisedRunsPlaceAllSixAndNoneIsLost 277
  PegTransferBatch.OnIdealServosNineteenOfTwentyRandomisedRunsPlaceAllSixAndNoneIsLost 195
  PegTransferOverRos.TheDefaultTwinPlacesAllSixAsItDoesInProcess 123
  Twin.SettledPosesMatchTheKinematicsWithinATenthOfAMillimetre 122
  ActiveLearning.ProposedMotionsIdentifyAHiddenRobotInFewerRecordingsThanRandomOnes 48
  Video.OfTheMainJobDecodesToItsFramesSizeAndSimulatedDuration 40
  StudyCli.VirtualParticipantsMoveRingsInThePegTransfer 40
  RavenAnalyze.ReportsTheTwinAsAThirdPlatformWithFigures 40
  ActuationFit.AShortFitImprovesOnItsStartingPoint 35)
while(raven_longest_tests)
  list(POP_FRONT raven_longest_tests name seconds)
  set_tests_properties(${name} PROPERTIES COST ${seconds})
endwhile()
