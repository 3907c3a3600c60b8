#!/usr/bin/env python

import smach


class ConditionalOutcomeState(smach.State):
    """Ends with the first outcome whose callback output is true, else `default`."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=[]):
        # Each condition's callback writes the key named like the outcome, which execute()
        # then reads: it is both an output and an input key.
        self._conditions = [o for o in outcomes if o != 'default']
        input_keys = list(input_keys) + [o for o in self._conditions if o not in input_keys]
        output_keys = list(output_keys) + [o for o in self._conditions if o not in output_keys]
        if 'outcome' not in output_keys:
            output_keys.append('outcome')
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=self._conditions + ['default'])
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        for outcome in self._conditions:
            if outcome in userdata and userdata[outcome]:
                userdata.outcome = outcome
                return outcome
        userdata.outcome = 'default'
        return 'default'


@smach.cb_interface(input_keys=['text'],
                    output_keys=['same'],
                    outcomes=['same', 'default'])
def same_check_22af0e8bf0a048a29a92d3c5940486c9_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.text == str(["a\u00a0b", "tab\tc", "é", "\u2028", "\U0001F600"]) + "_x"
    userdata.same = lambda_cb(userdata)
    return 'succeeded'


def main():
    python_text_unicode = smach.StateMachine(outcomes=['same', 'different'])
    python_text_unicode.userdata.text = "['a\\xa0b', 'tab\\tc', 'é', '\\u2028', '😀']_x"

    with python_text_unicode:
        smach.StateMachine.add('CHECK',
                               ConditionalOutcomeState(input_keys = ['text'], callbacks = ['same_check_22af0e8bf0a048a29a92d3c5940486c9_lambda_cb'], outcomes=['same', 'default']),
                               transitions={'default':'different',
                                            'same':'same'})

    outcome = python_text_unicode.execute()


if __name__ == '__main__':
    main()
