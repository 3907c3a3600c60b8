"""What each script of SMACHA's test corpus comes to under smachac (smacha_corpus.py):
the outcome its top state machine reaches on the real SMACH (run_smach.py seeds `random`),
or the diagnostic that rejects it. Keys are <package>/<group>/<script name>."""

EXPECTED = {
    "smacha/smacha_test_examples/assigned_params": "final_outcome",
    "smacha/smacha_test_examples/assigned_params_shorthand": "final_outcome",
    "smacha/smacha_test_examples/callbacks": "final_outcome",
    "smacha/smacha_test_examples/callbacks_shorthand": "final_outcome",
    "smacha/smacha_test_examples/hard_coded_params": "final_outcome",
    "smacha/smacha_test_examples/nesting_params": "final_outcome",
    "smacha/smacha_test_examples/nesting_params_shorthand": "final_outcome",
    "smacha/smacha_test_examples/nesting_params_with_sub_script": "final_outcome",
    "smacha/smacha_test_examples/print_userdata": "final_outcome",
    "smacha/smacha_test_examples/print_userdata_shorthand": "final_outcome",
    "smacha/smacha_test_examples/random_outcomes": "final_outcome",
    "smacha/smacha_test_examples/seq": "final_outcome_a",
    "smacha/smacha_test_examples/seq_concurrence_1": "final_outcome_a",
    "smacha/smacha_test_examples/seq_concurrence_1_shorthand": "final_outcome_a",
    "smacha/smacha_test_examples/seq_concurrence_2": "final_outcome_a",
    "smacha/smacha_test_examples/seq_concurrence_2_shorthand": "final_outcome_a",
    "smacha/smacha_test_examples/seq_concurrence_3": "final_outcome_a",
    "smacha/smacha_test_examples/seq_concurrence_3_shorthand": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_1": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_1_shorthand": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_1_super_script": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_2": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_2_shorthand": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_2_super_script": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_3": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_3_shorthand": "final_outcome_a",
    "smacha/smacha_test_examples/seq_nesting_3_super_script": "final_outcome_a",
    "smacha/executive_smach_tutorials/concurrence2": "outcome6",
    "smacha/executive_smach_tutorials/state_machine2": "outcome4",
    "smacha/executive_smach_tutorials/state_machine_nesting2": "outcome5",
    "smacha/executive_smach_tutorials/state_machine_nesting2_shorthand": "outcome5",
    "smacha/executive_smach_tutorials/user_data2": "outcome4",
    "smacha_ros/smacha_test_examples/publish_msg_1": "succeeded",
    "smacha_ros/smacha_test_examples/rosbag_api_recording_1": "succeeded",
    "smacha_ros/smacha_test_examples/rosbag_api_recording_2": "succeeded",
    "smacha_ros/smacha_test_examples/rosbag_api_recording_3": "succeeded",
    "smacha_ros/smacha_test_examples/rosbag_cli_recording_1": "succeeded",
    "smacha_ros/smacha_test_examples/rosbag_cli_recording_2": "succeeded",
    "smacha_ros/smacha_test_examples/rosbag_cli_recording_3": "succeeded",
    "smacha_ros/smacha_test_examples/sleep": "final_outcome",
    "smacha_ros/executive_smach_tutorials/actionlib2_test": "succeeded",
    "smacha_ros/executive_smach_tutorials/concurrence2": "outcome6",
    "smacha_ros/executive_smach_tutorials/service_test": "succeeded",
    "smacha_ros/executive_smach_tutorials/state_machine2": "outcome4",
    "smacha_ros/executive_smach_tutorials/state_machine_nesting2": "outcome5",
    "smacha_ros/executive_smach_tutorials/state_machine_nesting2_shorthand": "outcome5",
    "smacha_ros/executive_smach_tutorials/user_data2": "outcome4",
}

# Scripts smachac rejects: (the diagnostic kind, the error SMACH itself raises when the program
# is compiled anyway with -Wno-error=KIND and run, why).
REJECTED = {
    "smacha/smacha_test_examples/seq_nesting_1_super_script_2": (
        "unknown-transition-target", "InvalidTransitionError",
        "SUB_0 and SUB_1 go to FOO_2, which no state is; SMACHA's own expected program has "
        "the same transitions"),
    "smacha/smacha_test_examples/seq_nesting_1_super_script_2_shorthand": (
        "unknown-transition-target", "InvalidTransitionError",
        "the same script in shorthand"),
}
