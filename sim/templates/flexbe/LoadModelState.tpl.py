{% block meta %}
name: LoadModelState
description: >
  Loads a model into Gazebo at a pose: the model of that name is deleted
  (/gazebo/delete_model), then spawned from its SDF or URDF file
  (/gazebo/spawn_sdf_model or /gazebo/spawn_urdf_model). Without model_path
  the file comes from baxter_sim_examples/models (table: cafe_table, blockN:
  block). A variable left out is read from the input key of the same name
  (pose; reference_frame when the script remaps it, else world). The frame
  base is Baxter's, baxter::base.
language: Python
framework: FlexBE
type: State
tags: [baxter]
includes: []
extends:
- State
variables:
- model_name:
    description: The name of the model in Gazebo (table, block1, block2, ...).
    type: str
- - model_path:
      description: The model's SDF or URDF file (default from baxter_sim_examples).
      type: str
- - pose:
      description: >
        The model's pose in reference_frame, [[x, y, z], [qx, qy, qz, qw]]
        (default: input key pose).
      type: list
- - reference_frame:
      description: world or base (default input key reference_frame, else world).
      type: str
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "BaxterUtils.tpl.py" import define_baxter_module, text_argument, data_argument, render_baxter_add %}
{% set state_module = '' %}
{% set state_class = 'LoadGazeboModelState' %}

{% block class_defs %}
{{ define_baxter_module(defined_headers) }}


{% if 'class_LoadGazeboModelState' not in defined_headers %}
class LoadGazeboModelState(BaxterEventState):
    """
    Loads a model into Gazebo at a pose, replacing any model of the same name.

    -- model_name       string  The model's name in Gazebo.
    -- model_path       string  Its SDF or URDF file (None: from baxter_sim_examples).
    -- pose             list    [[x, y, z], [qx, qy, qz, qw]] (None: the input key pose).
    -- reference_frame  string  world or base (Baxter's).
    -- input_keys       list    The arguments read from the userdata.

    ># pose             list    The pose, when pose is an input key.
    ># reference_frame  string  The frame, when reference_frame is an input key.

    <= succeeded                Gazebo spawned the model.
    <= aborted                  It did not.
    <= preempted                The behavior was preempted.
    """

    MODEL_FILES = {'table': 'cafe_table/model.sdf', 'block': 'block/model.urdf'}
    FRAMES = {'base': 'baxter::base'}
    SERVICE_TIMEOUT = 5.0  # seconds to wait for Gazebo's services

    def __init__(self, model_name, model_path=None, pose=None, reference_frame='world',
                 input_keys=[]):
        BaxterEventState.__init__(self, dict(model_name=model_name, model_path=model_path,
                                             pose=pose, reference_frame=reference_frame),
                                  input_keys)

    def model_file(self, model_name):
        kind = model_name.rstrip('0123456789_')
        try:
            models = os.path.join(rospkg.RosPack().get_path('baxter_sim_examples'), 'models')
        except rospkg.ResourceNotFound as error:
            raise ValueError('no model_path and no baxter_sim_examples: %s' % error)
        return os.path.join(models, self.MODEL_FILES.get(kind, kind + '/model.urdf'))

    def call(self, service_name, service_type, *arguments, **fields):
        rospy.wait_for_service(service_name, self.SERVICE_TIMEOUT)
        return rospy.ServiceProxy(service_name, service_type)(*arguments, **fields)

    def start(self, userdata, model_name, model_path, pose, reference_frame):
        path = model_path or self.model_file(model_name)
        with open(path) as model_file:
            model_xml = model_file.read()
        self.call('/gazebo/delete_model', DeleteModel, model_name)
        kind = 'sdf' if path.endswith('.sdf') else 'urdf'
        response = self.call('/gazebo/spawn_%s_model' % kind, SpawnModel,
                             model_name=model_name, model_xml=model_xml, robot_namespace='/',
                             initial_pose=baxter_pose_msg(pose),
                             reference_frame=self.FRAMES.get(reference_frame, reference_frame))
        if not response.success:
            Logger.logerr('%s: %s' % (type(self).__name__, response.status_message))
        return 'succeeded' if response.success else 'aborted'
{% do defined_headers.append('class_LoadGazeboModelState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- set arguments = [text_argument('model_name', model_name)] %}
{%- set keys = [] %}
{%- if model_path is defined %}{% do arguments.append(text_argument('model_path', model_path)) %}{% endif %}
{%- if pose is defined %}{% do arguments.append(data_argument('pose', pose)) %}{% else %}{% do keys.append('pose') %}{% endif %}
{%- if reference_frame is defined %}{% do arguments.append(text_argument('reference_frame', reference_frame)) %}
{%- elif remapping is defined and 'reference_frame' in remapping %}{% do keys.append('reference_frame') %}{% endif %}
{{ render_baxter_add(defined_headers, default_module, state_class, name, arguments, keys, [], transitions, autonomy, remapping) }}
{% endblock body %}
