# The GoogleTest cases over half a minute, with their durations in seconds as measured here
# (ctest -j2, 2 cores, 2026-12-05), so that ctest starts the costliest first: a fresh build tree
# has no costs of its own, and in declaration order the longest (the batches, the study) would
# start last and run alone on one core. Included after the cases are discovered; the other long
# tests carry their COST where tests/CMakeLists.txt declares them.
set(raven_longest_tests
  PegTransferBatch.TheGraspAssistPinsEveryRingWholeOnTheNominalAndTwentyRandomisedScenes 371
  StudyCli.TheExampleFindsTheDegradedSchemeWorseWithEightVirtualParticipants 367
  PegTransferBatch.OnTheMotorTwinNineteenOfTwentyRandomisedRunsPlaceAllSixAndNoneIsLost 266
  PegTransferOverRos.TheDefaultTwinPlacesAllSixAsItDoesInProcess 201
  PegTransferBatch.OnIdealServosNineteenOfTwentyRandomisedRunsPlaceAllSixAndNoneIsLost 157
  Twin.SettledPosesMatchTheKinematicsWithinATenthOfAMillimetre 127
  StudyCli.VirtualParticipantsMoveRingsInThePegTransfer 51
  RavenAnalyze.ReportsTheTwinAsAThirdPlatformWithFigures 50
  Video.OfTheMainJobDecodesToItsFramesSizeAndSimulatedDuration 43
  ActuationFit.AShortFitImprovesOnItsStartingPoint 41
  ActiveLearning.ProposedMotionsIdentifyAHiddenRobotInFewerRecordingsThanRandomOnes 39)
while(raven_longest_tests)
  list(POP_FRONT raven_longest_tests name seconds)
  set_tests_properties(${name} PROPERTIES COST ${seconds})
endwhile()
