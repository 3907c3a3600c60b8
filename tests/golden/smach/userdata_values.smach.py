#!/usr/bin/env python

import smach


class PrintUserdataState(smach.State):
    """Logs every input key with its value, in the order given, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._keys = list(dict.fromkeys(input_keys))  # in order (SMACH keeps a set)

    def execute(self, userdata):
        for key in self._keys:
            smach.loginfo('userdata.{}: {}'.format(key, userdata[key]))
        return 'succeeded'


def main():
    values = smach.StateMachine(outcomes=['done'])
    values.userdata.a_bool = True
    values.userdata.a_dict = {'k': 'v', 'n': 1}
    values.userdata.a_float = 0.1
    values.userdata.a_list = [1, 'two', 3.5, ['nested']]
    values.userdata.an_int = 3
    values.userdata.backslash = 'C:\\temp'
    values.userdata.both_quotes = 'say "it\'s"'
    values.userdata.call = Point()
    values.userdata.code = [x * 2 for x in range(3)]
    values.userdata.dotted = geometry_msgs.msg.Point
    values.userdata.float_text = 1e3
    values.userdata.forced_dotted = 'data.csv'
    values.userdata.forced_number = '1.5'
    values.userdata.newline = 'two\nlines'
    values.userdata.nothing = None
    values.userdata.plain = 'hello world'
    values.userdata.quote = "it's"


    with values:
        smach.StateMachine.add('SHOW',
                               PrintUserdataState(input_keys = ['an_int', 'plain']),
                               transitions={'succeeded':'done'})

    outcome = values.execute()


if __name__ == '__main__':
    main()
